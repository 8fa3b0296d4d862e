// Rigid sphere contact: consistent stiffness, Hertz (with mesh
// refinement), thin bonded layer, input checks
#include "RigidSphereContact.H"
#include "SolidError.H"
#include "SolidTestUtils.H"
#include "StaticSolver.H"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

using namespace solid;

namespace
{

//- Dense -df/du of all contributions at u, time t
Eigen::MatrixXd contactStiffness
(
    Model& model,
    const Eigen::VectorXd& u,
    double t
)
{
    const int n = model.nDisplacementDofs();
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
    Triplets K;
    for (const auto& c : model.contributions()) c->addForce(model, u, t, f, &K);
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
    for (const auto& tr : K) D(tr.row(), tr.col()) += tr.value();
    return D;
}

Eigen::VectorXd contactForce(Model& model, const Eigen::VectorXd& u, double t)
{
    Eigen::VectorXd f = Eigen::VectorXd::Zero(model.nDisplacementDofs());
    for (const auto& c : model.contributions())
    {
        c->addForce(model, u, t, f, nullptr);
    }
    return f;
}

//- Relative difference of the analytic and the central-difference
//  stiffness, with the multipliers set to lambdas (some zero)
double stiffnessError(Model& model, RigidSphereContact& c, double h)
{
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> U(0, 1);
    const std::size_t nq = c.penalties(model).size();
    std::vector<double> lambda(nq);
    for (auto& l : lambda) l = U(gen) < 0.5 ? 0.0 : 50*U(gen);
    c.setMultipliers(lambda);
    Eigen::VectorXd u(model.nDisplacementDofs());
    for (int i = 0; i < u.size(); ++i) u(i) = 0.02*h*(U(gen) - 0.5);
    const Eigen::MatrixXd K = contactStiffness(model, u, 0.0);
    Eigen::MatrixXd Kfd(K.rows(), K.cols());
    const double du = 1e-7*h;
    for (int j = 0; j < u.size(); ++j)
    {
        Eigen::VectorXd up = u, um = u;
        up(j) += du;
        um(j) -= du;
        Kfd.col(j) = -(contactForce(model, up, 0) - contactForce(model, um, 0))
            /(2*du);
    }
    const ContactReport r = c.report(model, u, 0.0);
    std::printf("  active points %d, |K| = %.3e\n", r.nActive, K.norm());
    EXPECT_GT(r.nActive, 0);
    return (K - Kfd).norm()/K.norm();
}

} // namespace


TEST(SolidContact, StiffnessMatchesFiniteDifferencesAxisymmetric)
{
    const double h = 1e-6;
    Mesh m = Mesh::rectangle(3, 2, 0, 3*h, 0, 2*h);
    Model model(m);
    model.setMaterial("solid", solidTest::material(100, 0));
    model.initialise();
    RigidSphereSettings s;
    s.radius = 4*h;
    // Penetrates the top over r < ~2.2 h (active and inactive points)
    s.centre0 = Vec3(0, 2*h + 4*h - 0.6*h, 0);
    s.depth = [](double) { return 0.0; };
    s.tolerance = 1e-3*h;
    auto c = std::make_shared<RigidSphereContact>("top", s);
    model.add(c);
    const double err = stiffnessError(model, *c, h);
    std::printf("r-z contact stiffness vs FD: relative error %.2e\n", err);
    EXPECT_LT(err, 1e-6);
}


TEST(SolidContact, StiffnessMatchesFiniteDifferences3D)
{
    const double h = 1e-6;
    Mesh m = Mesh::box(2, 2, 1, Vec3(0, 0, 0), Vec3(2*h, 2*h, h));
    Model model(m);
    model.setMaterial("solid", solidTest::material(100, 0));
    model.initialise();
    RigidSphereSettings s;
    s.radius = 3*h;
    s.centre0 = Vec3(0.7*h, 0.9*h, h + 3*h - 0.4*h);
    s.direction = Vec3(0, 0, -1);
    s.depth = [](double) { return 0.0; };
    s.tolerance = 1e-3*h;
    auto c = std::make_shared<RigidSphereContact>("zmax", s);
    model.add(c);
    const double err = stiffnessError(model, *c, h);
    std::printf("3D contact stiffness vs FD: relative error %.2e\n", err);
    EXPECT_LT(err, 1e-6);
}


namespace
{

struct IndentResult
{
    std::vector<double> depth, force;
    int iterations = 0, augmentations = 0;
    double seconds = 0, maxPenetration = 0, contactRadius = 0;
};

//- Rigid sphere (radius R) pressed to depth dMax in nSteps equal steps
//  into an incompressible neo-Hookean cylinder (radius W, height H,
//  bottom bonded, side free), n x n elements graded geometrically towards
//  the first contact point (r = 0, z = H)
IndentResult indent
(
    int n, double R, double dMax, double W, double H, double mu, int nSteps,
    double tolerance
)
{
    const auto t0 = std::chrono::steady_clock::now();
    Mesh m = Mesh::rectangle(n, n, 0, 1, 0, 1);
    const double beta = 4.0;
    const auto g = [beta](double s)
    {
        return std::expm1(beta*s)/std::expm1(beta);
    };
    m.map([&](const Vec3& X)
    {
        return Vec3(W*g(X(0)), H*(1 - g(1 - X(1))), 0);
    });
    Model model(m);
    model.setMaterial("solid", solidTest::material(mu/2, 0));
    model.fix("bottom", 0);
    model.fix("bottom", 1);
    model.fix("left", 0);
    RigidSphereSettings s;
    s.radius = R;
    s.centre0 = Vec3(0, H + R, 0);
    s.direction = Vec3(0, -1, 0);
    s.depth = [dMax](double t) { return dMax*t; };
    s.tolerance = tolerance;
    auto c = std::make_shared<RigidSphereContact>("top", s);
    model.add(c);
    model.initialise();
    StaticSolver solver(model);
    IndentResult res;
    for (int k = 0; k < nSteps; ++k)
    {
        const StepReport rep = solver.step(1.0/nSteps);
        res.iterations += rep.iterations;
        res.augmentations += rep.augmentations;
        const ContactReport cr = c->report(model, model.u, model.time);
        res.depth.push_back(s.depth(model.time));
        res.force.push_back(cr.force);
        res.maxPenetration = cr.maxPenetration;
        res.contactRadius = cr.contactRadius;
    }
    res.seconds = std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();
    return res;
}

double hertz(double mu, double R, double d)
{
    return 16.0/3.0*mu*std::sqrt(R)*std::pow(d, 1.5);
}

//- Bonded incompressible layer of thickness h (Dimitriadis et al. 2002,
//  Biophys. J. 82:2798, eq. 12 with nu = 0.5), chi = sqrt(R d)/h
double bondedLayerFactor(double chi)
{
    return 1 + 1.133*chi + 1.283*chi*chi + 0.769*std::pow(chi, 3)
        + 0.0975*std::pow(chi, 4);
}

} // namespace


// Reference: Hertz, F = (16/3) mu sqrt(R) d^1.5 (incompressible, E* = 4 mu),
// times the bonded-layer factor of the cylinder's finite height H = 20 a
// (chi = a/H = 0.05: +6.0 %). Bound 3 % on the finest mesh and on the
// Richardson extrapolation: the reference itself carries about 1-2 % (the
// Dimitriadis polynomial is a fit of a small-strain series for a layer of
// infinite extent, here the side is free at W = 20 a: doubling W was
// measured to raise F by 1.3 % (the coarse mesh then resolves the contact
// too poorly for a monotone sequence, hence W = 20 a); sphere
// against paraboloid and finite strain at a/R = 0.07), the penetration
// tolerance 1e-3 d lowers F by ~1.5e-3. The discretisation error must
// converge at an observed order > 1.5 (Q1 elements, smooth pressure
// except at the contact edge).
TEST(SolidContact, HertzIncompressibleNeoHookeanConvergesWithMesh)
{
    const double R = 22.5e-6, mu = 1000;
    const double d = 0.005*R;               // a/R = 0.07
    const double a = std::sqrt(R*d);
    const double H = 20*a, W = 20*a;
    const double Fh = hertz(mu, R, d)*bondedLayerFactor(a/H);
    std::vector<double> F;
    for (int n : {12, 24, 48})
    {
        const IndentResult r = indent(n, R, d, W, H, mu, 4, 1e-3*d);
        F.push_back(r.force.back());
        std::printf
        (
            "Hertz n = %2d: F = %.5e N, F_Hertz*layer = %.5e N, error "
            "%+.2f %%, a = %.3f a_Hertz, penetration %.1e m, %d Newton "
            "iterations, %d augmentations, %.2f s\n",
            n, F.back(), Fh, 100*(F.back()/Fh - 1), r.contactRadius/a,
            r.maxPenetration, r.iterations, r.augmentations, r.seconds
        );
        EXPECT_LE(r.maxPenetration, 1e-3*d);
    }
    const double order = solidTest::order
    (
        std::abs(F[0] - F[1]), std::abs(F[1] - F[2])
    );
    const double Fx = F[2] + (F[2] - F[1])/(std::pow(2.0, order) - 1);
    std::printf
    (
        "observed order %.2f, extrapolated F = %.5e N (%+.2f %% of the "
        "reference)\n", order, Fx, 100*(Fx/Fh - 1)
    );
    EXPECT_GT(order, 1.5);
    EXPECT_LT(std::abs(F[2]/Fh - 1), 0.03);
    EXPECT_LT(std::abs(Fx/Fh - 1), 0.03);
}


// Thin bonded layer (H = 2 a at the final depth): F/F_Hertz grows with the
// depth (chi = sqrt(R d)/H) and exceeds the thick block's; the small-strain
// theory of Dimitriadis et al. is met within 10 % up to chi = 0.5 (its
// series is truncated at chi^4 and the layer strain reaches d/H = 3.5 %)
TEST(SolidContact, ThinBondedLayerStiffensFasterThanHertz)
{
    const double R = 22.5e-6, mu = 1000;
    const double d = 0.005*R;
    const double a = std::sqrt(R*d);
    const double W = 20*a;
    const IndentResult thick = indent(24, R, d, W, 20*a, mu, 4, 1e-3*d);
    const IndentResult thin = indent(24, R, d, W, 2*a, mu, 4, 1e-3*d);
    double previous = 0;
    for (std::size_t k = 0; k < thin.force.size(); ++k)
    {
        const double dk = thin.depth[k];
        const double ratio = thin.force[k]/hertz(mu, R, dk);
        const double ratioThick = thick.force[k]/hertz(mu, R, dk);
        const double theory = bondedLayerFactor(std::sqrt(R*dk)/(2*a));
        std::printf
        (
            "d = %.3e m: F/F_Hertz thin %.3f (Dimitriadis %.3f), thick "
            "%.3f\n", dk, ratio, theory, ratioThick
        );
        EXPECT_GT(ratio, previous);
        EXPECT_GT(ratio, ratioThick);
        EXPECT_LT(std::abs(ratio/theory - 1), 0.10);
        previous = ratio;
    }
}


TEST(SolidContact, BadInputIsRejected)
{
    RigidSphereSettings s;
    s.radius = -1;
    s.tolerance = 1e-9;
    s.depth = [](double) { return 0.0; };
    EXPECT_THROW(RigidSphereContact("top", s), SolidError);
    s.radius = 1e-5;
    s.tolerance = 0;
    EXPECT_THROW(RigidSphereContact("top", s), SolidError);

    // Off-axis centre in r-z
    s.tolerance = 1e-9;
    s.centre0 = Vec3(1e-6, 0, 0);
    Model model(Mesh::rectangle(2, 2, 0, 1e-6, 0, 1e-6));
    model.setMaterial("solid", solidTest::material(100, 0));
    model.add(std::make_shared<RigidSphereContact>("top", s));
    model.initialise();
    Eigen::VectorXd f = Eigen::VectorXd::Zero(model.nDisplacementDofs());
    EXPECT_THROW
    (
        model.contributions()[0]->addForce(model, model.u, 0, f, nullptr),
        SolidError
    );
}
