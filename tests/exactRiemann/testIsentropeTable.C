/*---------------------------------------------------------------------------*\
Description
    riemann::isentropeTable: the ambient isentrope tabulated on both sides of
    the ambient pressure, with the Riemann-invariant integral F(p). Checked
    against the closed-form ideal-gas isentrope and, for water's
    Mie-Grueneisen law, against an independent fixed-step RK4 integration
    of de/drho = p/rho^2, dF/drho = c/rho written here (not
    riemann::isentrope); the inverse p(F) against F(p).
\*---------------------------------------------------------------------------*/

#include "isentropeTable.H"
#include "IdealGas.H"
#include "riemannTestTools.H"
#include <gtest/gtest.h>
#include <array>
#include <cmath>
#include <iostream>

namespace
{

//- One RK4 step of (e, F) in rho, by h
template<class Eos>
void rk4(const Eos& eos, double& rho, double& e, double& F, double h)
{
    auto f = [&](double r, double ee, double& de, double& dF)
    {
        de = eos.p(r, ee)/(r*r);
        dF = std::sqrt(eos.c2(r, ee))/r;
    };
    double k1e, k1F, k2e, k2F, k3e, k3F, k4e, k4F;
    f(rho, e, k1e, k1F);
    f(rho + h/2, e + h/2*k1e, k2e, k2F);
    f(rho + h/2, e + h/2*k2e, k3e, k3F);
    f(rho + h, e + h*k3e, k4e, k4F);
    e += h/6*(k1e + 2*k2e + 2*k3e + k4e);
    F += h/6*(k1F + 2*k2F + 2*k3F + k4F);
    rho += h;
}

} // namespace


TEST(isentropeTable, idealGasMatchesClosedFormAtFourthOrder)
{
    const double gamma = 1.4;
    const eos::IdealGas air(eos::IdealGas::Parameters{gamma, 717.5});
    const double rhoA = 1.2, pA = 1e5;
    const double eA = pA/((gamma - 1)*rhoA);
    const double cA = std::sqrt(gamma*pA/rhoA);
    // Largest errors over 998 pressures of [0.3, 8] pA: F (of cA), rho,
    // e and p(F(p)) (relative)
    auto errors = [&](std::size_t n)
    {
        const auto t =
            riemann::isentropeTable::build(air, rhoA, eA, 0.3*pA, 8*pA, n);
        std::array<double, 4> err{0, 0, 0, 0};
        for (int i = 0; i <= 997; ++i)
        {
            const double p = 0.3*pA + (8 - 0.3)*pA*i/997.0;
            const double rho = rhoA*std::pow(p/pA, 1/gamma);
            const double c = std::sqrt(gamma*p/rho);
            const double F = 2/(gamma - 1)*(c - cA);
            err[0] = std::max(err[0], std::abs(t.F(p) - F)/cA);
            err[1] = std::max(err[1], std::abs(t.rho(p)/rho - 1));
            err[2] = std::max(err[2], std::abs(t.e(p)*(gamma - 1)*rho/p - 1));
            err[3] = std::max(err[3], std::abs(t.pressure(t.F(p))/p - 1));
        }
        EXPECT_NEAR(t.F(pA), 0, 1e-8*cA);
        return err;
    };
    const auto coarse = errors(401), fine = errors(1601);
    const char* names[] = {"F", "rho", "e", "p(F)"};
    for (int k = 0; k < 4; ++k)
    {
        const double order = std::log(coarse[k]/fine[k])/std::log(4.0);
        std::cout << "[ measured ] ideal gas " << names[k] << ": error "
            << coarse[k] << " / " << fine[k] << " at 401 / 1601 nodes, "
            << "order " << order << std::endl;
        EXPECT_GT(order, 3.7) << names[k];
        EXPECT_LT(fine[k], 1e-9) << names[k];
    }
}


TEST(isentropeTable, waterMatchesIndependentIntegration)
{
    const eos::MieGruneisen water = riemannTest::water();
    const double rhoA = 1000, eA = water.e(rhoA, 0.0);
    const double pLow = -20e6, pHigh = 400e6;
    const auto t = riemann::isentropeTable::build
    (
        water, rhoA, eA, pLow, pHigh
    );
    // RK4 from the ambient state both ways in density, 2e5 steps each,
    // compared wherever it passes a tabulated pressure range
    double maxF = 0, maxRho = 0, maxE = 0, maxInv = 0;
    int compared = 0;
    for (const double sign : {1.0, -1.0})
    {
        double rho = rhoA, e = eA, F = 0;
        const double h = sign*0.2/2e5*rhoA;
        for (int k = 0; k < 200000; ++k)
        {
            rk4(water, rho, e, F, h);
            const double p = water.p(rho, e);
            if (p > pHigh || p < pLow) break;
            if (k % 1000 == 999)
            {
                const double c = std::sqrt(water.c2(rho, e));
                maxF = std::max(maxF, std::abs(t.F(p) - F)/c);
                maxRho = std::max(maxRho, std::abs(t.rho(p)/rho - 1));
                maxE = std::max(maxE, std::abs(t.e(p) - e)/(c*c));
                maxInv = std::max(maxInv, std::abs(t.pressure(F) - p)/pHigh);
                ++compared;
            }
        }
    }
    std::cout << "[ measured ] water, " << t.size() << " nodes, "
        << compared << " points: F " << maxF << " (of c), rho " << maxRho
        << ", e " << maxE << " (of c^2), p(F) " << maxInv << " (of pHigh)"
        << std::endl;
    EXPECT_GT(compared, 50);
    EXPECT_LT(maxF, 1e-10);
    EXPECT_LT(maxRho, 1e-10);
    EXPECT_LT(maxE, 1e-10);
    EXPECT_LT(maxInv, 1e-10);
    // The linear acoustic limit near ambient: F = dp/(rho0 c0)
    const double c0 = std::sqrt(water.c2(rhoA, eA));
    EXPECT_NEAR(t.F(1e3), 1e3/(rhoA*c0), 1e-6*1e3/(rhoA*c0));
}


TEST(isentropeTable, outsideTheTableThrows)
{
    const eos::MieGruneisen water = riemannTest::water();
    const double eA = water.e(1000, 0.0);
    const auto t =
        riemann::isentropeTable::build(water, 1000, eA, -1e6, 1e8, 101);
    EXPECT_THROW(t.F(1.1e8), std::out_of_range);
    EXPECT_THROW(t.rho(-2e6), std::out_of_range);
    EXPECT_THROW(t.pressure(1e3), std::out_of_range);
    EXPECT_THROW(t.F(std::nan("")), std::out_of_range);
    EXPECT_THROW
    (
        riemann::isentropeTable::build(water, 1000, eA, 1e6, 1e8),
        std::invalid_argument
    );
}
