/*---------------------------------------------------------------------------*\
Description
    Ideal and stiffened gas: domain checks and parameter validation (the
    consistency checks are in testEosConsistency.C).
\*---------------------------------------------------------------------------*/

#include "IdealGas.H"
#include "StiffenedGas.H"
#include <gtest/gtest.h>
#include <string>

namespace
{

template<class Eos>
void expectParameterError
(
    const typename Eos::Parameters& par,
    const std::string& name
)
{
    try
    {
        Eos law(par);
        ADD_FAILURE() << "no ParameterError for " << name;
    }
    catch (const eos::ParameterError& err)
    {
        EXPECT_NE
        (
            std::string(err.what()).find("parameter " + name + " ="),
            std::string::npos
        ) << err.what();
    }
}

} // namespace


TEST(idealGas, nonPositiveEnergyHasNoSoundSpeed)
{
    const eos::IdealGas air({1.4, 717.5});
    EXPECT_EQ(air.check(1.2, 0), eos::Status::nonPositiveSoundSpeed);
    EXPECT_EQ(air.check(1.2, -1), eos::Status::nonPositiveSoundSpeed);
    EXPECT_EQ(air.check(1.2, 2e5), eos::Status::ok);
    EXPECT_TRUE(std::isnan(air.rho(-1e5, 2e5)));
}


TEST(idealGas, parameterErrorsNameTheParameter)
{
    expectParameterError<eos::IdealGas>({1.0, 717.5}, "gamma");
    expectParameterError<eos::IdealGas>({0.5, 717.5}, "gamma");
    expectParameterError<eos::IdealGas>({1.4, 0}, "Cv");
    expectParameterError<eos::IdealGas>({1.4, -1}, "Cv");
}


TEST(stiffenedGas, tensionBeyondMinusPInfHasNoSoundSpeed)
{
    const eos::StiffenedGas water({4.4, 6e8, 4184});
    const double rho = 1000;
    const double eOk = water.e(rho, -5e8);
    const double eBad = water.e(rho, -6.5e8);
    EXPECT_EQ(water.check(rho, eOk), eos::Status::ok);
    EXPECT_LE(water.c2(rho, eBad), 0);
    EXPECT_EQ(water.check(rho, eBad), eos::Status::nonPositiveSoundSpeed);
}


TEST(stiffenedGas, parameterErrorsNameTheParameter)
{
    expectParameterError<eos::StiffenedGas>({1.0, 6e8, 4184}, "gamma");
    expectParameterError<eos::StiffenedGas>({4.4, -1, 4184}, "pInf");
    expectParameterError<eos::StiffenedGas>({4.4, 6e8, 0}, "Cv");
    // finite but beyond the physical bounds (physicalBounds.H)
    expectParameterError<eos::StiffenedGas>({4.4, 1e300, 4184}, "pInf");
    expectParameterError<eos::StiffenedGas>({4.4, 6e8, 1e300}, "Cv");
    // pInf = 0 is allowed (ideal gas)
    EXPECT_NO_THROW(eos::StiffenedGas({1.4, 0, 717.5}));
}
