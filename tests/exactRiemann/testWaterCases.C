/*---------------------------------------------------------------------------*\
Description
    Exact Riemann solutions for Mie-Grueneisen water (rho0 = 1000 kg/m^3,
    C0 = 1450 m/s, s = 1.99, Gamma0 = 0.1): a single 50 MPa shock, 1 GPa
    released into ambient water, two colliding 50 MPa states, tension
    (modest: valid; strong: domainError), the weak-wave acoustic limit.
    Checks: Rankine-Hugoniot conditions across every shock (1e-8 relative
    to the jumps), continuity at the fan ends, the fan energy against the
    closed-form integral of the MG isentrope, conservation over a domain
    between two times.
\*---------------------------------------------------------------------------*/

#include "exactRiemannSolver.H"
#include "riemannTestTools.H"
#include <gtest/gtest.h>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>

using namespace riemannTest;
using riemann::exactRiemannSolver;
using riemann::primitiveState;
using riemann::waveType;

namespace
{

using solver = exactRiemannSolver<eos::MieGruneisen>;

//- Reference state at rest, p = 0, e = 0
const primitiveState ambient{1000.0, 0.0, 0.0};

//- The post-shock state of a shock of pressure pS into the reference
//  state, moving with velocity sign*up
primitiveState shocked(double pS, double sign)
{
    const auto law = water();
    const double up = law.particleVelocity(pS);
    return {law.hugoniotDensity(up), sign*up, pS};
}

//- Cold (e = 0) water at rest at pressure p
primitiveState cold(double p)
{
    return {water().rho(p, 0), 0.0, p};
}

void printStar(const char* name, const solver& rp)
{
    const auto& s = rp.star();
    std::cout << "[ measured ] " << name << ": p* = " << s.p
        << " Pa, u* = " << s.u << " m/s, rho*L = " << s.rhoL
        << " kg/m^3, rho*R = " << s.rhoR << " kg/m^3, "
        << s.iterations << " Newton iterations; left "
        << riemann::waveTypeName(rp.waves().left.type) << ", right "
        << riemann::waveTypeName(rp.waves().right.type) << std::endl;
}

//- Jump conditions across the left and/or right wave if it is a shock
void expectShockJumps(const solver& rp)
{
    const auto& w = rp.waves();
    const auto& s = rp.star();
    // A wave whose pressure jump is at rounding level has no measurable
    // jump to check
    const double pScale =
        std::abs(rp.left().p) + std::abs(rp.right().p) + std::abs(s.p);
    auto strong = [&](double pK) { return std::abs(s.p - pK) > 1e-9*pScale; };
    int nShocks = 0;
    if (w.left.type == waveType::shock && strong(rp.left().p))
    {
        const auto r = shockJump
        (
            rp.sample(w.left.headSpeed - 1),
            {s.rhoL, s.u, s.p, s.eL},
            w.left.headSpeed
        );
        EXPECT_LT(r.mass, 1e-8);
        EXPECT_LT(r.momentum, 1e-8);
        EXPECT_LT(r.energy, 1e-8);
        ++nShocks;
    }
    if (w.right.type == waveType::shock && strong(rp.right().p))
    {
        const auto r = shockJump
        (
            {s.rhoR, s.u, s.p, s.eR},
            rp.sample(w.right.headSpeed + 1),
            w.right.headSpeed
        );
        EXPECT_LT(r.mass, 1e-8);
        EXPECT_LT(r.momentum, 1e-8);
        EXPECT_LT(r.energy, 1e-8);
        ++nShocks;
    }
    EXPECT_GT(nShocks, 0);
}

//- Both sides of each fan end agree to first order in the offset d of
//  the ray: |dp| <= rho c |d|, |du| <= |d|, |drho| <= rho |d|/c
void expectContinuousFans(const solver& rp)
{
    const auto& w = rp.waves();
    for (const auto& wv : {w.left, w.right})
    {
        if (wv.type != waveType::rarefaction) continue;
        for (const double xi : {wv.headSpeed, wv.tailSpeed})
        {
            const double d = 1e-9*std::abs(xi);
            const auto a = rp.sample(xi - d);
            const auto b = rp.sample(xi + d);
            const double c = std::sqrt(rp.eos().c2(a.rho, a.e));
            EXPECT_NEAR(a.p, b.p, 2*d*a.rho*c) << "xi " << xi;
            EXPECT_NEAR(a.u, b.u, 2*d) << "xi " << xi;
            EXPECT_NEAR(a.rho, b.rho, 2*d*a.rho/c) << "xi " << xi;
        }
    }
}

} // namespace


TEST(waterRiemann, singleShockMovesAtC0PlusSUp)
{
    const auto law = water();
    const primitiveState left = shocked(50e6, +1);
    const solver rp(law, left, ambient);
    printStar("single 50 MPa shock", rp);
    const double up = left.u;

    EXPECT_NEAR(rp.star().p, 50e6, 1e-10*50e6);
    EXPECT_NEAR(rp.star().u, up, 1e-10*up);
    EXPECT_NEAR(rp.star().rhoL, left.rho, 1e-12*left.rho);
    // Zero-strength left wave (the left state is already on the Hugoniot)
    EXPECT_NEAR(rp.star().eL, law.hugoniotEnergy(up), 1e-6);
    ASSERT_EQ(rp.waves().right.type, waveType::shock);
    EXPECT_NEAR
    (
        rp.waves().right.headSpeed, law.shockSpeed(up),
        1e-10*law.shockSpeed(up)
    );
    EXPECT_NEAR(rp.star().rhoR, left.rho, 1e-10*left.rho);
    expectShockJumps(rp);
}


TEST(waterRiemann, release1GPaIntoAmbientWater)
{
    const auto law = water();
    const solver rp(law, cold(1e9), cold(1e5));
    printStar("1 GPa release", rp);

    ASSERT_EQ(rp.waves().left.type, waveType::rarefaction);
    ASSERT_EQ(rp.waves().right.type, waveType::shock);
    EXPECT_GT(rp.star().p, 1e5);
    EXPECT_LT(rp.star().p, 1e9);
    EXPECT_GT(rp.star().u, 0);
    EXPECT_EQ(law.check(rp.star().rhoL, rp.star().eL), eos::Status::ok);
    expectShockJumps(rp);
    expectContinuousFans(rp);
}


TEST(waterRiemann, fanEnergyFollowsTheMieGrueneisenIsentrope)
{
    // With Gamma rho = Gamma0 rho0 = k constant, de/dv = -p = -pCold(v) - k e
    // integrates with the factor exp(k v):
    //   e(v) = eA exp(-k (v - vA)) - int_vA^v pCold(v') exp(-k (v - v')) dv'
    // evaluated here by Gauss-Legendre quadrature, independent of the
    // solver's Runge-Kutta integration in ln rho.
    const auto law = water();
    const solver rp(law, cold(1e9), cold(1e5));
    const double k = 0.1*1000;
    const double vA = 1/rp.left().rho;
    const double eA = law.e(rp.left().rho, rp.left().p);
    auto pCold = [&](double v) { return law.p(1/v, 0); };
    auto eExact = [&](double v)
    {
        static const double gx[5] =
        {
            -0.9061798459386640, -0.5384693101056831, 0.0,
            0.5384693101056831, 0.9061798459386640
        };
        static const double gw[5] =
        {
            0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
            0.4786286704993665, 0.2369268850561891
        };
        const int n = 200;
        const double h = (v - vA)/n;
        double I = 0;
        for (int j = 0; j < n; ++j)
        {
            for (int g = 0; g < 5; ++g)
            {
                const double vp = vA + (j + 0.5 + 0.5*gx[g])*h;
                I += 0.5*h*gw[g]*pCold(vp)*std::exp(-k*(v - vp));
            }
        }
        return eA*std::exp(-k*(v - vA)) - I;
    };

    const auto& w = rp.waves().left;
    double maxErr = 0, maxChange = 0;
    for (int i = 0; i <= 20; ++i)
    {
        const double xi = w.headSpeed + (w.tailSpeed - w.headSpeed)*i/20.0;
        const auto q = rp.sample(xi);
        maxErr = std::max(maxErr, std::abs(q.e - eExact(1/q.rho)));
        maxChange = std::max(maxChange, std::abs(q.e - eA));
        // On the fan u - c = xi
        EXPECT_NEAR(q.u - std::sqrt(law.c2(q.rho, q.e)), xi, 1e-9*1450);
    }
    std::cout << "[ measured ] fan energy error " << maxErr
        << " J/kg for an energy change of " << maxChange << " J/kg"
        << std::endl;
    EXPECT_GT(maxChange, 1e3);
    EXPECT_LT(maxErr, 1e-9*maxChange);
}


TEST(waterRiemann, symmetricCollisionHasZeroStarVelocity)
{
    const auto law = water();
    const primitiveState left = shocked(50e6, +1);
    const primitiveState right = shocked(50e6, -1);
    const solver rp(law, left, right);
    printStar("colliding 50 MPa states", rp);

    EXPECT_NEAR(rp.star().u, 0, 1e-12*left.u);
    EXPECT_NEAR(rp.star().rhoL, rp.star().rhoR, 1e-12*left.rho);
    EXPECT_NEAR
    (
        rp.waves().left.headSpeed, -rp.waves().right.headSpeed,
        1e-10*rp.waves().right.headSpeed
    );
    ASSERT_EQ(rp.waves().left.type, waveType::shock);
    ASSERT_EQ(rp.waves().right.type, waveType::shock);
    // Stopping the flow takes more than doubling the pressure
    EXPECT_GT(rp.star().p, 100e6);
    expectShockJumps(rp);
}


TEST(waterRiemann, modestTensionGivesTwoRarefactions)
{
    // Each side pulled with the velocity that, acoustically, gives -2 MPa
    const auto law = water();
    const double du = 2e6/(1000*1450);
    const solver rp(law, {1000, -du, 0}, {1000, du, 0});
    printStar("2 MPa tension", rp);

    EXPECT_EQ(rp.waves().left.type, waveType::rarefaction);
    EXPECT_EQ(rp.waves().right.type, waveType::rarefaction);
    EXPECT_NEAR(rp.star().u, 0, 1e-12*du);
    // Acoustic -2 MPa up to O(amplitude): eps = 2e6/(rho0 C0^2) ~ 1e-3
    const double eps = 2e6/(1000*1450.0*1450.0);
    EXPECT_NEAR(rp.star().p, -2e6, 2*1.99*eps*2e6);
    EXPECT_LT(rp.star().rhoL, 1000);
    EXPECT_GT(law.c2(rp.star().rhoL, rp.star().eL), 0);
    expectContinuousFans(rp);
}


TEST(waterRiemann, tensionCloseToTheCavitationLimitIsStillValid)
{
    // Each rarefaction from the reference state supplies up to ~305.5 m/s
    // before c^2 -> 0 (p ~ -261 MPa)
    const auto law = water();
    const solver rp(law, {1000, -300, 0}, {1000, 300, 0});
    printStar("300 m/s pull", rp);
    EXPECT_LT(rp.star().p, -200e6);
    EXPECT_GT(law.c2(rp.star().rhoL, rp.star().eL), 0);
    EXPECT_NEAR(rp.star().u, 0, 1e-9);
}


TEST(waterRiemann, strongTensionThrowsNamingTheSoundSpeed)
{
    const auto law = water();
    try
    {
        const solver rp(law, {1000, -400, 0}, {1000, 400, 0});
        ADD_FAILURE() << "no domainError, p* = " << rp.star().p;
    }
    catch (const riemann::domainError& err)
    {
        std::cout << "[ measured ] " << err.what() << std::endl;
        EXPECT_EQ(err.status(), eos::Status::nonPositiveSoundSpeed);
        EXPECT_EQ(err.where(), "left rarefaction");
        EXPECT_NE(std::string(err.what()).find("c^2 <= 0"), std::string::npos);
    }
}


TEST(waterRiemann, initialStateOutsideTheLawThrows)
{
    const auto law = water();
    // Past the Hugoniot limit rho0/(1 - 1/s) = 2010 kg/m^3
    EXPECT_THROW(solver(law, {2100, 0, 1e9}, ambient), riemann::domainError);
    EXPECT_THROW(solver(law, ambient, {-1, 0, 0}), riemann::domainError);
}


TEST(waterRiemann, weakWaveApproachesLinearAcoustics)
{
    // A 1 kPa (and 2 kPa) jump: u* -> dp/(2 rho0 C0), p* -> dp/2 with an
    // error O(dp^2), i.e. the error doubles twice when dp doubles
    const auto law = water();
    const double Z0 = 1000*1450.0;
    double du[2], dp[2];
    for (int k = 0; k < 2; ++k)
    {
        const double jump = 1e3*(k + 1);
        const solver rp(law, cold(jump), ambient);
        const double uAc = jump/(2*Z0);
        du[k] = rp.star().u - uAc;
        dp[k] = rp.star().p - 0.5*jump;
        const double eps = jump/(Z0*1450);
        EXPECT_LT(std::abs(du[k]), 2*1.99*eps*uAc);
        EXPECT_LT(std::abs(dp[k]), 2*1.99*eps*jump);
        // The right shock runs into the reference state: the general
        // Hugoniot must reproduce Us = C0 + s up, p = rho0 Us up, to the
        // rounding of rho amplified by the weak compression:
        // 10 eps rho/(rho - rho0)
        const double u = rp.star().u;
        const double tol =
            10*std::numeric_limits<double>::epsilon()
           *rp.star().rhoR/(rp.star().rhoR - 1000);
        EXPECT_NEAR(rp.star().p, 1000*(1450 + 1.99*u)*u, tol*rp.star().p);
        EXPECT_NEAR
        (
            rp.waves().right.headSpeed, 1450 + 1.99*u, tol*1450
        );
        std::cout << "[ measured ] " << jump << " Pa jump: u* = "
            << rp.star().u << " m/s (acoustic " << uAc << "), p* = "
            << rp.star().p << " Pa" << std::endl;
    }
    std::cout << "[ measured ] error ratios u: " << du[1]/du[0]
        << ", p: " << dp[1]/dp[0] << std::endl;
    EXPECT_NEAR(du[1]/du[0], 4, 0.05);
    EXPECT_NEAR(dp[1]/dp[0], 4, 0.05);
}


TEST(waterRiemann, conservationOverADomainBetweenTwoTimes)
{
    const auto law = water();
    const double t1 = 1e-6, t2 = 3e-6;
    const double L = 4000*t2;
    for
    (
        const auto& states
      : {
            std::make_pair(cold(1e9), cold(1e5)),
            std::make_pair(shocked(50e6, 1), shocked(50e6, -1)),
            std::make_pair
            (
                primitiveState{1000, -50, 0}, primitiveState{1000, 50, 0}
            ),
            std::make_pair(cold(2e8), shocked(50e6, -1))
        }
    )
    {
        const solver rp(law, states.first, states.second);
        const auto rel = conservationImbalance(rp, -L, L, t1, t2);
        EXPECT_LT(rel[0], 1e-10) << "mass";
        EXPECT_LT(rel[1], 1e-10) << "momentum";
        EXPECT_LT(rel[2], 1e-10) << "energy";
        std::cout << "[ measured ] imbalance mass " << rel[0]
            << " momentum " << rel[1] << " energy " << rel[2] << std::endl;
    }
}
