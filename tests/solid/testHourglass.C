// Viscous hourglass control of the explicit driver (ExplicitSettings::
// hourglass): it damps the element velocity patterns that change no element
// volume (the hourglass modes of the Q1/P0 element, which a cell-like
// material with shear moduli of 1e2 Pa against a bulk modulus of 2 GPa
// does not resist), leaves every linear velocity field alone, and its
// dissipation closes the energy balance. r-z quads and hexahedra.
#include "ExplicitSolver.H"
#include "SolidError.H"
#include "SolidTestUtils.H"

#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>

using namespace solid;

namespace
{

// One free element of size 1 um (r-z ring at r in [2, 3] um, or a cube)
std::unique_ptr<Model> element(bool axi)
{
    const double h = 1e-6;
    Mesh m = axi ? Mesh::rectangle(1, 1, 2*h, 3*h, 0, h)
                 : Mesh::box(1, 1, 1, Vec3(0, 0, 0), Vec3(h, h, h));
    std::unique_ptr<Model> model(new Model(m));
    model->setMaterial(m.regionNames[0], solidTest::cytoplasm());
    model->initialise();
    return model;
}

// Node coordinate relative to the element centre, in half sizes (+-1)
double xi(const Model& m, int node, int i)
{
    const Mesh& mesh = m.mesh();
    double lo = 1e300, hi = -1e300;
    for (int a = 0; a < mesh.nNodes(); ++a)
    {
        lo = std::min(lo, mesh.X[a](i));
        hi = std::max(hi, mesh.X[a](i));
    }
    return (2*mesh.X[node](i) - lo - hi)/(hi - lo);
}

// Hourglass velocity pattern: axial (r-z: z; 3D: x) velocity
// V xi eta (r-z) or V eta zeta (3D), 1 m/s
void hourglassVelocity(Model& m)
{
    const int dim = m.mesh().dim();
    for (int a = 0; a < m.mesh().nNodes(); ++a)
    {
        m.v(dim*a + (dim == 2 ? 1 : 0)) =
            dim == 2 ? xi(m, a, 0)*xi(m, a, 1) : xi(m, a, 1)*xi(m, a, 2);
    }
}

// Linear velocity field: translation + uniform strain rate, 1 m/s scale
void linearVelocity(Model& m)
{
    const int dim = m.mesh().dim();
    for (int a = 0; a < m.mesh().nNodes(); ++a)
    {
        for (int i = 0; i < dim; ++i)
        {
            m.v(dim*a + i) = 0.3 + 0.5*xi(m, a, i) - 0.2*xi(m, a, (i + 1)%dim);
        }
    }
    if (dim == 2)
    {
        // r-z: v_r = a r keeps the hoop rate uniform as well
        for (int a = 0; a < m.mesh().nNodes(); ++a)
        {
            m.v(dim*a) = 0.5*m.mesh().X[a](0)/3e-6;
        }
    }
}

double kineticEnergy(const Model& m)
{
    return 0.5*m.v.dot(m.lumpedMass().cwiseProduct(m.v));
}

void checkHourglassDamped(bool axi)
{
    const int steps = 100;
    double ke[2] = {0, 0}, ke0 = 0, balance = 0, dissipated = 0;
    double fhg0 = 0, fhg1 = 0;
    for (int k = 0; k < 2; ++k)
    {
        auto model = element(axi);
        hourglassVelocity(*model);
        ke0 = kineticEnergy(*model);
        ExplicitSettings set;
        set.safety = 0.5;           // a single free element: 0.8 of L/c
                                    // is beyond its highest frequency
        set.hourglass = k == 0 ? 0 : 0.1;
        ExplicitSolver solver(*model, set);
        if (k == 1) fhg0 = solver.hourglassForce().norm();
        for (int s = 0; s < steps; ++s) solver.step();
        ke[k] = kineticEnergy(*model);
        if (k == 1)
        {
            fhg1 = solver.hourglassForce().norm();
            balance = solver.energy().balance();
            dissipated = solver.energy().hourglass;
        }
    }
    std::printf("%s hourglass pattern, %d steps: KE/KE0 %.3e without, "
        "%.3e with kappa 0.1; hourglass force (velocity) %.3e of its "
        "start; hourglass dissipation %.4e J of KE0 %.4e J, balance %.2e "
        "of KE0\n", axi ? "r-z" : "3D", steps, ke[0]/ke0, ke[1]/ke0,
        fhg1/fhg0, dissipated, ke0, balance/ke0);
    // Undamped: the shear moduli (1e2 Pa) keep almost all of it moving
    EXPECT_GT(ke[0], 0.99*ke0);
    // Damped: the hourglass velocity is gone, its energy dissipated (in r-z
    // the pattern also changes the ring volume: that part rings on
    // undamped, there is no bulk viscosity here)
    EXPECT_LT(fhg1, 1e-3*fhg0);
    EXPECT_GT(dissipated, (axi ? 0.9 : 0.999)*ke0);
    EXPECT_LT(std::abs(balance), 1e-3*ke0);
}

void checkLinearFieldUntouched(bool axi)
{
    // The hourglass force of a linear velocity field is zero (round-off)
    {
        auto model = element(axi);
        ExplicitSettings set;
        set.hourglass = 0.1;
        hourglassVelocity(*model);
        const double fPattern =
            ExplicitSolver(*model, set).hourglassForce().norm();
        linearVelocity(*model);
        const double fLinear =
            ExplicitSolver(*model, set).hourglassForce().norm();
        std::printf("%s: hourglass force of a linear field %.2e of that "
            "of the hourglass pattern\n", axi ? "r-z" : "3D",
            fLinear/fPattern);
        EXPECT_LT(fLinear, 1e-12*fPattern);
    }
    if (axi) return;    // r-z: the hoop stress makes any field nonlinear

    // 3D: a linear field stays linear, the motion is that without damping
    const int steps = 50;
    Eigen::VectorXd u[2], v[2];
    for (int k = 0; k < 2; ++k)
    {
        auto model = element(axi);
        linearVelocity(*model);
        ExplicitSettings set;
        set.safety = 0.5;
        set.hourglass = k == 0 ? 0 : 0.1;
        ExplicitSolver solver(*model, set);
        for (int s = 0; s < steps; ++s) solver.step();
        u[k] = model->u;
        v[k] = model->v;
    }
    const double du = (u[1] - u[0]).norm()/u[0].norm();
    const double dv = (v[1] - v[0]).norm()/v[0].norm();
    std::printf("3D linear field, %d steps: relative difference u %.2e, "
        "v %.2e\n", steps, du, dv);
    EXPECT_LT(du, 1e-12);
    EXPECT_LT(dv, 1e-12);
}

} // namespace


TEST(SolidHourglass, DampsHourglassModeAxisymmetric)
{
    checkHourglassDamped(true);
}


TEST(SolidHourglass, DampsHourglassMode3D)
{
    checkHourglassDamped(false);
}


TEST(SolidHourglass, LinearVelocityFieldUntouchedAxisymmetric)
{
    checkLinearFieldUntouched(true);
}


TEST(SolidHourglass, LinearVelocityFieldUntouched3D)
{
    checkLinearFieldUntouched(false);
}


TEST(SolidHourglass, RejectsCoefficientOutOfRange)
{
    auto model = element(true);
    ExplicitSettings set;
    set.hourglass = 2;
    EXPECT_THROW(ExplicitSolver(*model, set), SolidError);
}


TEST(SolidHourglass, PerRegionCoefficient)
{
    // hourglassRegions overrides hourglass in the named region: kappa 0.1
    // given only for the element's region damps the pattern as the global
    // 0.1 does; 0 for its region under a global 0.1 leaves it undamped
    double ke[3];
    for (int k = 0; k < 3; ++k)
    {
        auto model = element(false);
        hourglassVelocity(*model);
        const std::string region = model->mesh().regionNames[0];
        ExplicitSettings set;
        set.safety = 0.5;
        set.hourglass = k == 1 ? 0 : 0.1;
        if (k == 1) set.hourglassRegions[region] = 0.1;
        if (k == 2) set.hourglassRegions[region] = 0;
        ExplicitSolver solver(*model, set);
        for (int s = 0; s < 100; ++s) solver.step();
        ke[k] = kineticEnergy(*model);
    }
    EXPECT_EQ(ke[0], ke[1]);                // the same damper, bitwise
    EXPECT_GT(ke[2], 1e3*ke[0]);            // undamped (KE/KE0 > 0.99 above)
}


TEST(SolidHourglass, RejectsUnknownRegion)
{
    auto model = element(false);
    ExplicitSettings set;
    set.hourglassRegions["membrane"] = 0.5;
    try
    {
        ExplicitSolver solver(*model, set);
        FAIL() << "no error for a region the mesh does not have";
    }
    catch (const SolidError& e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("region 'membrane'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("no such region"), std::string::npos) << msg;
    }
    set.hourglassRegions.clear();
    set.hourglassRegions[model->mesh().regionNames[0]] = 1.5;
    EXPECT_THROW(ExplicitSolver(*model, set), SolidError);
}
