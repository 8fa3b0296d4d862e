// The deviatoric numerical viscosity of the explicit solver
// (ExplicitSettings::shearViscosity, solidProperties shearViscosity): no
// force on rigid translation or uniform dilatation, a uniform shear rate
// dissipates 2 eta |dev D|^2 per volume with eta = beta rho0 c h, the
// energy balance closes, and a plane shock on an irregular mesh leaves a
// residue that converges with the element size (without it the mean
// dilatation's does not: bench/solid/README.md).
#include "../../bench/solid/planeShockColumn.H"
#include "ExplicitSolver.H"
#include "SolidError.H"
#include "SolidTestUtils.H"

#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>

using namespace solid;

namespace
{

// One free hexahedron [0, h]^3 with one corner moved (not a cube)
std::unique_ptr<Model> hex()
{
    const double h = 1e-6;
    Mesh m = Mesh::box(1, 1, 1, Vec3(0, 0, 0), Vec3(h, h, h));
    m.X[6] += Vec3(0.1*h, 0.05*h, -0.1*h);
    std::unique_ptr<Model> model(new Model(m));
    model->setMaterial(m.regionNames[0], solidTest::cytoplasm());
    model->initialise();
    return model;
}

// Dissipation of one step of the damper alone (no hourglass viscosity)
// for the initial nodal velocities set by v(X), relative to the kinetic
// energy: energy().hourglass after one step
double oneStepDissipation
(
    Model& m,
    const std::function<Vec3(const Vec3&)>& v,
    double beta,
    double* dt = nullptr,
    bool filter = false,
    bool byRegion = false
)
{
    const Mesh& mesh = m.mesh();
    for (int a = 0; a < mesh.nNodes(); ++a)
    {
        const Vec3 va = v(mesh.X[a]);
        for (int i = 0; i < mesh.dim(); ++i) m.v(mesh.dim()*a + i) = va(i);
    }
    ExplicitSettings set;
    set.safety = 1e-3;
    set.shearViscosity = beta;
    set.shearViscosityFilter = filter || byRegion;
    set.shearViscosityFilterByRegion = byRegion;
    ExplicitSolver solver(m, set);
    const double step = solver.step();
    if (dt) *dt = step;
    return solver.energy().hourglass;
}

// A bar of n x 2 x 2 hexahedra of size h along x, interior nodes moved
// randomly by up to frac h
std::unique_ptr<Model> bar(int n, double frac)
{
    const double h = 1e-6;
    Mesh m = Mesh::box(n, 2, 2, Vec3(0, 0, 0), Vec3(n*h, 2*h, 2*h));
    if (frac > 0) solidTest::distortInterior(m, h, frac, 3);
    std::unique_ptr<Model> model(new Model(m));
    model->setMaterial(m.regionNames[0], solidTest::cytoplasm());
    model->initialise();
    return model;
}

//- A bar of n x 3 x 3 hexahedra of size h along x in two regions, "left"
//  (x < n h/2) and "right", both of the cytoplasm's law; nodes off the
//  bar's faces and off the plane between the regions moved randomly by up
//  to frac h (the plane stays flat: a velocity linear on each side is
//  linear in every element)
std::unique_ptr<Model> twoRegionBar(int n, double frac)
{
    const double h = 1e-6;
    Mesh m = Mesh::box(n, 3, 3, Vec3(0, 0, 0), Vec3(n*h, 3*h, 3*h));
    m.regionNames = {"left", "right"};
    for (int e = 0; e < m.nElements(); ++e)
    {
        double x = 0;
        for (int a = 0; a < m.nen(); ++a) x += m.X[m.element(e)[a]](0);
        m.region[e] = x/m.nen() < 0.5*n*h ? 0 : 1;
    }
    std::vector<int> plane;
    for (int a = 0; a < m.nNodes(); ++a)
    {
        if (std::abs(m.X[a](0) - 0.5*n*h) < 1e-3*h) plane.push_back(a);
    }
    m.nodeSets["plane"] = plane;
    if (frac > 0) solidTest::distortInterior(m, h, frac, 5);
    std::unique_ptr<Model> model(new Model(m));
    model->setMaterial("left", solidTest::cytoplasm());
    model->setMaterial("right", solidTest::cytoplasm());
    model->initialise();
    return model;
}

//- One-step dissipation of the filtered damper over the plain one's for
//  the velocity field v on the bar (also returns both)
double filteredOverPlain
(
    int n,
    double frac,
    const std::function<Vec3(const Vec3&)>& v,
    double* plain = nullptr,
    double* filtered = nullptr
)
{
    auto a = bar(n, frac);
    auto b = bar(n, frac);
    const double dP = oneStepDissipation(*a, v, 0.1);
    const double dF = oneStepDissipation(*b, v, 0.1, nullptr, true);
    if (plain) *plain = dP;
    if (filtered) *filtered = dF;
    return dF/dP;
}

} // namespace


TEST(shearViscosity, uniformShearDissipatesTwoEtaDevDSquared)
{
    // v_x = g y: D_xy = g/2, |dev D|^2 = g^2/2, so the rate 2 eta V g^2/2
    const double g = 1e4, beta = 0.1;
    auto m = hex();
    const ElementOutput o = m->evaluateElement(0, 0);
    const double V = m->geometry(0).V;
    const double eta =
        beta*m->material(0).rho0()*std::sqrt(o.c2)*std::cbrt(V);
    double dt = 0;
    const double d = oneStepDissipation
    (
        *m, [g](const Vec3& X) { return Vec3(g*X(1), 0, 0); }, beta, &dt
    );
    const double exact = eta*V*g*g*dt;
    std::printf("uniform shear: dissipation %.6e J in one step of %.3e s, "
        "2 eta |dev D|^2 V dt = %.6e J\n", d, dt, exact);
    EXPECT_NEAR(d, exact, 2e-3*exact);
}


TEST(shearViscosity, noForceOnTranslationOrDilatation)
{
    const double beta = 0.1;
    double reference = 0;
    {
        auto m = hex();
        reference = oneStepDissipation
        (
            *m, [](const Vec3& X) { return Vec3(1e4*X(1), 0, 0); }, beta
        );
    }
    auto translation = hex();
    const double dT = oneStepDissipation
    (
        *translation, [](const Vec3&) { return Vec3(0.3, -0.2, 0.1); }, beta
    );
    auto dilatation = hex();
    const double dD = oneStepDissipation
    (
        *dilatation, [](const Vec3& X) { return Vec3(1e4*X); }, beta
    );
    // r-z: a distorted ring, axial translation and v = (a r, a z)
    double dRz = 0, refRz = 0;
    for (const bool shear : {false, true})
    {
        const double h = 1e-6;
        Mesh mesh = Mesh::rectangle(1, 1, 2*h, 3*h, 0, h);
        mesh.X[2] += Vec3(0.2*h, 0.1*h, 0);
        Model m(mesh);
        m.setMaterial(mesh.regionNames[0], solidTest::cytoplasm());
        m.initialise();
        const double d = oneStepDissipation
        (
            m,
            [shear](const Vec3& X)
            {
                return shear ? Vec3(0, 1e4*X(0), 0)
                             : Vec3(1e4*X(0), 1e4*X(1) + 0.5, 0);
            },
            beta
        );
        (shear ? refRz : dRz) = d;
    }
    std::printf("one-step dissipation: shear %.3e J; translation %.3e, "
        "dilatation %.3e J; r-z shear %.3e J, dilatation + translation "
        "%.3e J\n", reference, dT, dD, refRz, dRz);
    EXPECT_GT(reference, 0);
    EXPECT_LT(std::abs(dT), 1e-12*reference);
    EXPECT_LT(std::abs(dD), 1e-9*reference);
    EXPECT_GT(refRz, 0);
    EXPECT_LT(std::abs(dRz), 1e-9*refRz);
}


TEST(shearViscosity, outOfRangeIsRefused)
{
    for (const double beta : {-0.1, 1.5, std::nan("")})
    {
        auto m = hex();
        ExplicitSettings set;
        set.shearViscosity = beta;
        EXPECT_THROW(ExplicitSolver(*m, set), SolidError) << beta;
    }
}


TEST(shearViscosity, planeShockResidueConverges)
{
    // A sharp shock (0.1 ns ramps) on the random mesh with the tutorials'
    // hourglass viscosity 0.1; the peak strain while passing is 0.022.
    // Measured (2026-12-03): rms residual strain 1.28e-3 (0.5 um) and
    // 1.29e-3 (0.25 um) without the damper; 5.0e-5 and 2.2e-5 with
    // beta 0.1. The energy balance with the damper's work in the hourglass
    // dissipation: 1.27e-3 of the external work at 0.25 um (5.8e-5
    // without it: the trapezoidal internal work du.(f_n + f_n+1)/2 against
    // velocity Verlet's kinetic energy differ by O(dt^2) terms that the
    // damper's rapidly changing forces make larger); bounded at 2e-3
    planeShock::Options o;
    o.mesh = "random";
    o.ramp = 0.1e-9;
    o.kappa = 0.1;
    o.h = 0.25e-6;
    const planeShock::Result without = planeShock::run(o);
    o.beta = 0.1;
    o.h = 0.5e-6;
    const planeShock::Result coarse = planeShock::run(o);
    o.h = 0.25e-6;
    const planeShock::Result fine = planeShock::run(o);
    std::printf("plane shock, random mesh, rms residual strain: beta 0.1 "
        "%.3e (0.5 um) %.3e (0.25 um); beta 0 %.3e (0.25 um); energy "
        "balance %.2e (beta 0: %.2e) of the external work\n",
        coarse.rmsStrain, fine.rmsStrain, without.rmsStrain, fine.balance,
        without.balance);
    EXPECT_LT(fine.rmsStrain, 0.7*coarse.rmsStrain);
    EXPECT_LT(fine.rmsStrain, 0.05*without.rmsStrain);
    EXPECT_LT(std::abs(fine.balance), 2e-3);
}


TEST(shearViscosity, filteredSparesUniformAndSmoothRatesNotNoise)
{
    // The filtered form (shearViscosityFilter): no force for a uniform
    // rate (also next to the boundary, on a distorted mesh); a smooth
    // shear wave of wave number k meets about (k h)^4/16 of the plain
    // dissipation in the interior (one-sided averages at the bar's ends
    // add more); an alternating (element-scale) pattern nearly all of it
    const int n = 32;
    const double h = 1e-6, L = n*h;
    double uP = 0, uF = 0;
    filteredOverPlain
    (
        n, 0.25, [](const Vec3& X) { return Vec3(1e4*X(1), 0, 0); },
        &uP, &uF
    );
    const double k = 2*M_PI/L;
    const double smooth = filteredOverPlain
    (
        n, 0, [k](const Vec3& X) { return Vec3(0, std::sin(k*X(0)), 0); }
    );
    const double noise = filteredOverPlain
    (
        n, 0,
        [h](const Vec3& X)
        {
            const long i = std::lround(X(0)/h);
            return Vec3(0, (i % 2 ? 1.0 : -1.0), 0);
        }
    );
    std::printf("filtered / plain dissipation: uniform shear %.3e J / "
        "%.3e J; smooth wave (k h = %.3f, (k h)^4/16 = %.2e) %.3e; "
        "alternating pattern %.3f\n", uF, uP, k*h,
        std::pow(k*h, 4)/16, smooth, noise);
    EXPECT_GT(uP, 0);
    EXPECT_LT(std::abs(uF), 1e-9*uP);
    EXPECT_LT(smooth, 3*std::pow(k*h, 4)/16);
    EXPECT_GT(noise, 0.9);
}


TEST(shearViscosity, filteredIsDissipativeAndBoundedByPlain)
{
    // Random nodal velocities on a distorted bar: the filtered damper's
    // dissipation is positive and below the plain one's (A is a
    // contraction in the w-weighted norm), so the plain stable-step
    // limit holds for it
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 5; ++trial)
    {
        std::vector<Vec3> vs;
        for (int a = 0; a < 200; ++a) vs.emplace_back(u(gen), u(gen), u(gen));
        double p = 0, f = 0;
        filteredOverPlain
        (
            8, 0.25,
            [&vs](const Vec3& X)
            {
                const long i = std::lround(X(0)*1e6)
                  + 9*std::lround(X(1)*1e6) + 27*std::lround(X(2)*1e6);
                return vs[i % vs.size()];
            },
            &p, &f
        );
        std::printf("random velocities %d: dissipation plain %.4e J, "
            "filtered %.4e J (%.3f)\n", trial, p, f, f/p);
        EXPECT_GT(f, 0);
        EXPECT_LT(f, p*(1 + 1e-9));
    }
}


TEST(shearViscosity, filteredKeepsThePulseAndCalmsTheColumn)
{
    // The plane shock on the random 0.5 um mesh (sharp: 0.1 ns ramps; and
    // a resolved front: 1 ns ramps). The plain damper at beta 0.1
    // attenuates the pulse (plateau pressure -4.7 % / -8.3 % against the
    // undamped run, measured 2026-12-03); the filtered one at beta 0.4
    // leaves it within 1 % and still removes most of the residue and
    // part of the element scatter of von Mises while the pulse passes
    for (const double ramp : {0.1e-9, 1e-9})
    {
        planeShock::Options o;
        o.mesh = "random";
        o.ramp = ramp;
        o.kappa = 0.1;
        o.h = 0.5e-6;
        const planeShock::Result none = planeShock::run(o);
        o.beta = 0.1;
        const planeShock::Result plain = planeShock::run(o);
        o.beta = 0.4;
        o.filter = true;
        const planeShock::Result filtered = planeShock::run(o);
        std::printf("ramp %.1f ns: plateau pressure / P: none %.5f, plain "
            "0.1 %.5f, filtered 0.4 %.5f; von Mises scatter %.3f / %.3f / "
            "%.3f; rms residue %.3e / %.3e / %.3e\n", ramp*1e9,
            none.plateauPressure, plain.plateauPressure,
            filtered.plateauPressure, none.plateauVonMisesRms,
            plain.plateauVonMisesRms, filtered.plateauVonMisesRms,
            none.rmsStrain, plain.rmsStrain, filtered.rmsStrain);
        EXPECT_LT(plain.plateauPressure, 0.97*none.plateauPressure);
        EXPECT_NEAR(filtered.plateauPressure, none.plateauPressure,
                    0.01*none.plateauPressure);
        EXPECT_LT(filtered.rmsStrain, 0.25*none.rmsStrain);
        EXPECT_LT(filtered.plateauVonMisesRms, 0.75*none.plateauVonMisesRms);
    }
}


TEST(shearViscosity, filterByRegionKeepsPiecewiseUniformRates)
{
    // Two regions of a bar in uniaxial strain at different rates, 1e4 /s
    // left and 3e4 /s right (v_x continuous, its slope jumping at the
    // plane between them), as the one-element membrane compressed more
    // than the cytoplasm under the blast's echo. The filter averaging
    // across the plane (shearViscosityFilter yes) sees the jump as a
    // departure and damps it in the elements at the plane; the per-region
    // filter (region) leaves each region's uniform rate alone. A uniform
    // shear over both regions is free for both; random velocities: the
    // per-region form is dissipative and bounded by the plain one
    const int n = 8;
    const double h = 1e-6, xm = 0.5*n*h;
    const auto jump = [xm](const Vec3& X)
    {
        const double x = X(0);
        return Vec3(x < xm ? 1e4*x : 1e4*xm + 3e4*(x - xm), 0, 0);
    };
    double plain = 0, mixed = 0, own = 0;
    {
        auto m = twoRegionBar(n, 0.25);
        plain = oneStepDissipation(*m, jump, 0.1);
    }
    {
        auto m = twoRegionBar(n, 0.25);
        mixed = oneStepDissipation(*m, jump, 0.1, nullptr, true);
    }
    {
        auto m = twoRegionBar(n, 0.25);
        own = oneStepDissipation(*m, jump, 0.1, nullptr, true, true);
    }
    double uniform = 0;
    {
        auto m = twoRegionBar(n, 0.25);
        uniform = oneStepDissipation
        (
            *m, [](const Vec3& X) { return Vec3(1e4*X(1), 0, 0); }, 0.1,
            nullptr, true, true
        );
    }
    std::printf("two regions, rates 1e4 / 3e4 1/s: dissipation plain "
        "%.4e J, filtered across regions %.4e J (%.3f of plain), per "
        "region %.3e J; uniform shear per region %.3e J\n", plain, mixed,
        mixed/plain, own, uniform);
    EXPECT_GT(plain, 0);
    EXPECT_GT(mixed, 1e-3*plain);
    EXPECT_LT(std::abs(own), 1e-9*plain);
    EXPECT_LT(std::abs(uniform), 1e-9*plain);

    // Random velocities: positive and never above the plain damper's
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 3; ++trial)
    {
        std::vector<Vec3> vs;
        for (int a = 0; a < 400; ++a) vs.emplace_back(u(gen), u(gen), u(gen));
        const auto random = [&vs](const Vec3& X)
        {
            const long i = std::lround(X(0)*1e6)
              + 9*std::lround(X(1)*1e6) + 37*std::lround(X(2)*1e6);
            return vs[i % vs.size()];
        };
        auto a = twoRegionBar(n, 0.25);
        auto b = twoRegionBar(n, 0.25);
        const double p = oneStepDissipation(*a, random, 0.1);
        const double f =
            oneStepDissipation(*b, random, 0.1, nullptr, true, true);
        std::printf("random velocities %d, two regions: plain %.4e J, per "
            "region %.4e J (%.3f)\n", trial, p, f, f/p);
        EXPECT_GT(f, 0);
        EXPECT_LT(f, p*(1 + 1e-9));
    }
}


TEST(shearViscosity, filterByRegionIsTheFilterOnOneRegion)
{
    // One region: the per-region filter is the filter (the same slots)
    const auto wave = [](const Vec3& X)
    {
        return Vec3(0.3*std::sin(2e5*X(0)), 0.1*std::cos(3e5*X(0)), 0);
    };
    auto a = bar(8, 0.25);
    auto b = bar(8, 0.25);
    const double f = oneStepDissipation(*a, wave, 0.1, nullptr, true);
    const double r = oneStepDissipation(*b, wave, 0.1, nullptr, true, true);
    std::printf("one region: filtered %.6e J, per region %.6e J\n", f, r);
    EXPECT_GT(f, 0);
    EXPECT_NEAR(r, f, 1e-12*f);
}
