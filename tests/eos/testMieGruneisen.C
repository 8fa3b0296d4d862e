/*---------------------------------------------------------------------------*\
Description
    Mie-Grueneisen water (rho0 = 1000 kg/m^3, C0 = 1450 m/s, s = 1.99,
    Gamma0 = 0.1, Cv = 4184 J/kg/K, T0 = 293.15 K): the reference Hugoniot
    against the Rankine-Hugoniot jump conditions and eq. 4 of Jerusalem &
    Dao, the domain checks and the parameter validation.
\*---------------------------------------------------------------------------*/

#include "MieGruneisen.H"
#include <gtest/gtest.h>

#include <sstream>
#include <cmath>
#include <string>

namespace
{

const eos::MieGruneisen::Parameters water{};

} // namespace


TEST(mieGruneisen, referenceHugoniotSatisfiesJumpConditions)
{
    const eos::MieGruneisen law(water);
    const double rho0 = water.rho0, C0 = water.C0, s = water.s;
    for (const double up : {1.0, 10.0, 33.0, 100.0, 500.0, 1000.0, 3000.0})
    {
        const double Us = law.shockSpeed(up);
        const double rho = law.hugoniotDensity(up);
        const double p = law.hugoniotPressure(up);
        const double e = law.hugoniotEnergy(up);

        EXPECT_DOUBLE_EQ(Us, C0 + s*up);
        // Mass, momentum, energy across the shock into (rho0, 0, p=0, e=0)
        EXPECT_NEAR(rho*(Us - up), rho0*Us, 1e-12*rho0*Us) << up;
        EXPECT_NEAR(p, rho0*Us*up, 1e-12*p) << up;
        EXPECT_NEAR(e, 0.5*p*(1/rho0 - 1/rho), 1e-12*e) << up;
        // Eq. 4: pH = rho0 C0^2 (1 - J)/(1 - s (1 - J))^2, J = rho0/rho
        const double J = rho0/rho;
        const double d = 1 - s*(1 - J);
        EXPECT_NEAR(p, rho0*C0*C0*(1 - J)/(d*d), 1e-10*p) << up;
        // The full law reproduces its reference curve
        EXPECT_NEAR(law.p(rho, e), p, 1e-10*p) << up;
        EXPECT_NEAR(law.particleVelocity(p), up, 1e-10*up) << up;
        EXPECT_EQ(law.check(rho, e), eos::Status::ok) << up;
    }
}


TEST(mieGruneisen, pastHugoniotLimitIsReported)
{
    const eos::MieGruneisen law(water);
    const double rhoMax = law.rhoMax();
    EXPECT_NEAR(rhoMax, water.rho0/(1 - 1/water.s), 1e-12*rhoMax);
    // 1 - rho0/rho >= 1/s
    EXPECT_EQ(law.check(rhoMax*(1 + 1e-12), 0), eos::Status::pastHugoniotLimit);
    EXPECT_EQ(law.check(1.2*rhoMax, 1e6), eos::Status::pastHugoniotLimit);
    // Just inside: huge but valid
    EXPECT_EQ(law.check(rhoMax*(1 - 1e-6), 0), eos::Status::ok);
}


TEST(mieGruneisen, strongTensionHasNonPositiveSoundSpeed)
{
    const eos::MieGruneisen law(water);
    // Modest tension (-2 MPa) is inside the law
    const double rhoT = law.rho(-2e6, 0);
    EXPECT_LT(rhoT, water.rho0);
    EXPECT_EQ(law.check(rhoT, 0), eos::Status::ok);
    // Strong tension: 1 - rho0/rho = -0.55 < -1/s, where c^2 < 0
    const double rho = water.rho0/1.55;
    EXPECT_LE(law.c2(rho, 0), 0);
    EXPECT_EQ(law.check(rho, 0), eos::Status::nonPositiveSoundSpeed);
}


TEST(mieGruneisen, densityInversionIsUniqueUpToTheLimit)
{
    // A solid-like set with Gamma0 = 2 s - 1 (Dugdale-MacDonald)
    const eos::MieGruneisen law({8930, 3940, 1.49, 1.98, 385, 293.15});
    for (const double eta : {-0.2, 0.05, 0.2, 0.3, 0.32})
    {
        const double rho = 8930/(1 - eta);
        for (const double e : {0.0, 1e5, 1e6})
        {
            ASSERT_EQ(law.check(rho, e), eos::Status::ok);
            EXPECT_NEAR(law.rho(law.p(rho, e), e), rho, 1e-12*rho)
                << "eta " << eta << " e " << e;
        }
    }
}


TEST(mieGruneisen, parameterErrorsNameTheParameter)
{
    auto expectError = [](eos::MieGruneisen::Parameters par, const char* name)
    {
        try
        {
            eos::MieGruneisen law(par);
            ADD_FAILURE() << "no ParameterError for " << name;
        }
        catch (const eos::ParameterError& err)
        {
            EXPECT_NE
            (
                std::string(err.what()).find
                (
                    std::string("parameter ") + name + " ="
                ),
                std::string::npos
            ) << err.what();
        }
    };
    auto with = [](auto member, double v)
    {
        eos::MieGruneisen::Parameters p;
        p.*member = v;
        return p;
    };
    using P = eos::MieGruneisen::Parameters;
    expectError(with(&P::rho0, 0), "rho0");
    expectError(with(&P::rho0, -1000), "rho0");
    expectError(with(&P::C0, -1450), "C0");
    expectError(with(&P::C0, 0), "C0");
    // finite but beyond the physical bounds (physicalBounds.H): rho0 C0^2
    // overflowed, a floating-point exception (issue 19, adv30 hg11, hg15)
    expectError(with(&P::C0, 1e200), "C0");
    expectError(with(&P::C0, 1e5), "C0");
    expectError(with(&P::rho0, 1e300), "rho0");
    expectError(with(&P::rho0, 1e-300), "rho0");
    expectError(with(&P::Cv, 1e300), "Cv");
    expectError(with(&P::T0, 1e300), "T0");
    EXPECT_NO_THROW(eos::MieGruneisen(with(&P::C0, 0.99e5)));
    expectError(with(&P::s, 0), "s");
    expectError(with(&P::s, -1), "s");
    expectError(with(&P::Gamma0, 0), "Gamma0");
    expectError(with(&P::Gamma0, -0.1), "Gamma0");
    // Gamma0 >= 2 s: the cold curve is not monotone, rho(p, e) not unique;
    // both parameters named, with the bound of each (adv32 s15: s = 1e-12
    // was reported as Gamma0 outside (0, 2e-12) without naming s)
    for (const P& par : {with(&P::Gamma0, 4.0), with(&P::s, 1e-12)})
    {
        try
        {
            eos::MieGruneisen law(par);
            ADD_FAILURE() << "no ParameterError for Gamma0 >= 2 s";
        }
        catch (const eos::ParameterError& err)
        {
            const std::string msg(err.what());
            std::ostringstream both;
            both << "parameters Gamma0 = " << par.Gamma0 << " - and s = "
                 << par.s << " -: Gamma0 must be below 2 s = " << 2*par.s;
            EXPECT_NE(msg.find(both.str()), std::string::npos) << msg;
            EXPECT_NE(msg.find("that of s is ("), std::string::npos) << msg;
        }
    }
    expectError(with(&P::Cv, 0), "Cv");
    expectError(with(&P::T0, -1), "T0");
    expectError(with(&P::C0, NAN), "C0");
}


TEST(mieGruneisen, stateBelowZeroKelvinIsReported)
{
    // T = T0 + e/Cv: a state of positive c^2 at T <= 0 K was valid
    // (issue 19: 0/T at -5 K ran to the end)
    const eos::MieGruneisen law(water);
    const double eCold = -1.01*water.Cv*water.T0;       // T = -0.01 T0
    EXPECT_GT(law.c2(water.rho0, eCold), 0);
    EXPECT_EQ(law.check(water.rho0, eCold),
              eos::Status::nonPositiveTemperature);
    EXPECT_EQ(law.check(water.rho0, -0.99*water.Cv*water.T0),
              eos::Status::ok);
}
