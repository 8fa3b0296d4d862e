// Follower pressure (force and load stiffness against finite differences)
// and the Contribution plug-in used later by rigid contact.
#include "Loads.H"
#include "Model.H"
#include "StaticSolver.H"
#include "SolidError.H"
#include "SolidTestUtils.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace solid;

namespace
{

double pressureStiffnessError(Model& model, const std::string& set)
{
    PressureLoad load(set, [](double) { return 3.7; });
    std::mt19937 gen(1);
    std::uniform_real_distribution<double> d(-0.1, 0.1);
    Eigen::VectorXd u(model.nDisplacementDofs());
    for (int i = 0; i < u.size(); ++i) u(i) = d(gen);
    const int n = int(u.size());
    Triplets t;
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
    load.addForce(model, u, 0, f, &t);
    Eigen::SparseMatrix<double> K(n, n);
    K.setFromTriplets(t.begin(), t.end());
    Eigen::MatrixXd Kd = K;
    Eigen::MatrixXd fd(n, n);
    const double h = 1e-7;
    for (int j = 0; j < n; ++j)
    {
        Eigen::VectorXd up = u, um = u;
        up(j) += h;
        um(j) -= h;
        Eigen::VectorXd fp = Eigen::VectorXd::Zero(n), fm = fp;
        load.addForce(model, up, 0, fp, nullptr);
        load.addForce(model, um, 0, fm, nullptr);
        fd.col(j) = -(fp - fm)/(2*h);
    }
    return (fd - Kd).norm()/Kd.norm();
}

// A linear spring support k [N/m] on the axial component of a node set:
// the simplest Contribution with a stiffness (contact follows the same
// interface)
class SpringSupport
:
    public Contribution
{
    std::vector<int> nodes_;
    int comp_;
    double k_;

public:

    SpringSupport(const std::vector<int>& nodes, int comp, double k)
    :
        nodes_(nodes), comp_(comp), k_(k)
    {}

    void addForce
    (
        const Model& model, const Eigen::VectorXd& u, double, Eigen::VectorXd& f,
        Triplets* K
    ) const override
    {
        const int dim = model.mesh().dim();
        for (int n : nodes_)
        {
            const int d = n*dim + comp_;
            f(d) -= k_*u(d);
            if (K) K->emplace_back(d, d, k_);
        }
    }
};

} // namespace


TEST(SolidLoads, FollowerPressureStiffness)
{
    Mesh h = Mesh::box(2, 1, 1, Vec3(0, 0, 0), Vec3(2, 1, 1));
    Model m3(h);
    m3.setMaterial("solid", solidTest::material(1, 1));
    m3.initialise();
    EXPECT_LT(pressureStiffnessError(m3, "zmax"), 1e-7);
    EXPECT_LT(pressureStiffnessError(m3, "xmin"), 1e-7);
    Mesh q = Mesh::rectangle(2, 2, 0.5, 1.5, 0, 1);
    Model m2(q);
    m2.setMaterial("solid", solidTest::material(1, 1));
    m2.initialise();
    EXPECT_LT(pressureStiffnessError(m2, "top"), 1e-7);
    EXPECT_LT(pressureStiffnessError(m2, "right"), 1e-7);
}


TEST(SolidLoads, ContributionPlugInCarriesTheLoad)
{
    // Block pressed by p on top, resting on springs instead of a support:
    // the springs carry p A in total and compress uniformly
    const double L = 1e-5, p = 20, k = 1e-3;
    Mesh m = Mesh::box(2, 2, 2, Vec3(0, 0, 0), Vec3(L, L, L));
    Model model(m);
    model.setMaterial("solid", solidTest::material(100, 0));
    model.fix("xmin", 0);
    model.fix("ymin", 1);
    model.add(std::make_shared<PressureLoad>("zmax",
        [=](double t) { return t*p; }));
    const auto& bottom = m.nodeSet("zmin");
    model.add(std::make_shared<SpringSupport>(bottom, 2, k));
    model.initialise();
    StaticSolver solver(model);
    const StepReport r = solver.step(1.0);
    EXPECT_LE(r.iterations, 8);
    // Global equilibrium: the springs carry the follower pressure times
    // the deformed top area (vector area of a bilinear face is exactly
    // (d1 x d2)/2)
    double Fsprings = 0, area = 0;
    for (int n : bottom) Fsprings += -k*model.u(3*n + 2);
    for (const auto& f : m.faceSet("zmax"))
    {
        Vec3 x[4];
        for (int a = 0; a < 4; ++a)
            x[a] = m.X[f[a]] + model.u.segment<3>(3*f[a]);
        area += 0.5*(x[2] - x[0]).cross(x[3] - x[1])(2);
    }
    std::printf("springs carry %.6e N, p a = %.6e N (a/A = %.4f)\n",
                Fsprings, p*area, area/(L*L));
    EXPECT_NEAR(Fsprings, p*area, 1e-9*p*L*L);
    EXPECT_GT(area, 1.01*L*L);     // the follower load saw the expansion
}


TEST(SolidLoads, NodalLoadAndFacePressures)
{
    // Nodal forces on the top of a block: reactions balance them
    const double L = 1e-5, F = 4e-9;
    Mesh m = Mesh::box(1, 1, 1, Vec3(0, 0, 0), Vec3(L, L, L));
    Model model(m);
    model.setMaterial("solid", solidTest::material(100, 1e-3));
    model.fix("xmin", 0);
    model.fix("ymin", 1);
    model.fix("zmin", 2);
    model.add(std::make_shared<NodalLoad>(m.nodeSet("zmax"), 2,
        [=](double t) { return -t*F/4; }));
    model.initialise();
    StaticSolver solver(model);
    solver.step(1.0);
    const Eigen::VectorXd r = solver.reactions();
    double Rz = 0;
    for (int n : m.nodeSet("zmin")) Rz += r(3*n + 2);
    EXPECT_NEAR(Rz, F, 1e-9*F);
    EXPECT_LT(model.u(3*m.nodeSet("zmax")[0] + 2), 0);

    // Per-face pressures: the resultant is sum p_f A_f
    Mesh q = Mesh::rectangle(3, 1, 0, 3, 0, 1);
    Model mq(q);
    mq.setMaterial("solid", solidTest::material(1, 1));
    mq.initialise();
    PressureLoad load("top", [](double) { return 2.0; });
    const std::vector<double> fp = {1.0, 0.0, 3.0};
    load.setFacePressures(fp);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(mq.nDisplacementDofs());
    load.addForce(mq, mq.u, 0, f, nullptr);
    double Fz = 0;
    for (int n = 0; n < q.nNodes(); ++n) Fz += f(2*n + 1);
    // Faces of the top set in order: annuli [0,1], [1,2], [2,3]
    const double exact = -2.0*M_PI*(1.0*1 + 0.0*(4 - 1) + 3.0*(9 - 4));
    EXPECT_NEAR(Fz, exact, 1e-12*std::abs(exact));
    load.setFacePressures({1.0});
    EXPECT_THROW(load.addForce(mq, mq.u, 0, f, nullptr), SolidError);
}


namespace
{

// Augmented-Lagrangian tie of one dof to a target value with a soft
// penalty: the augmentation loop must drive the gap to its tolerance
class AugmentedTie
:
    public Contribution
{
    int dof_;
    double target_, k_, tol_;
    double lambda_ = 0, lambdaCommitted_ = 0;

public:

    int passes = 0;

    AugmentedTie(int dof, double target, double k, double tol)
    :
        dof_(dof), target_(target), k_(k), tol_(tol)
    {}

    void addForce
    (
        const Model&, const Eigen::VectorXd& u, double, Eigen::VectorXd& f,
        Triplets* K
    ) const override
    {
        f(dof_) -= lambda_ + k_*(u(dof_) - target_);
        if (K) K->emplace_back(dof_, dof_, k_);
    }

    bool augment(const Model&, const Eigen::VectorXd& u, double) override
    {
        ++passes;
        const double gap = u(dof_) - target_;
        if (std::abs(gap) <= tol_) return false;
        lambda_ += k_*gap;
        return true;
    }

    void commit(const Model&, const Eigen::VectorXd&, double) override
    {
        lambdaCommitted_ = lambda_;
    }

    void revert() override { lambda_ = lambdaCommitted_; }
};

} // namespace

TEST(SolidLoads, NodalLoadGivenForces)
{
    // Forces per node and component (the FSI coupling's interface forces)
    // land on their dofs, are replaced by the next setForces(), and a
    // wrong count or a time-function load is refused
    Mesh m = Mesh::rectangle(2, 1, 0, 2, 0, 1);
    Model model(m);
    model.setMaterial("solid", solidTest::material(1, 1));
    model.initialise();
    const std::vector<int> nodes = {4, 1};
    NodalLoad load(nodes, 2);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(model.nDisplacementDofs());
    load.addForce(model, model.u, 0, f, nullptr);
    EXPECT_EQ(f.norm(), 0);
    load.setForces({1.5, -2.0, 0.25, 3.0});
    f.setOnes();
    load.addForce(model, model.u, 0, f, nullptr);
    Eigen::VectorXd expected = Eigen::VectorXd::Ones(f.size());
    expected(2*4) += 1.5;
    expected(2*4 + 1) += -2.0;
    expected(2*1) += 0.25;
    expected(2*1 + 1) += 3.0;
    EXPECT_EQ(f, expected);
    load.setForces({0, 0, 0, 1});
    f.setZero();
    load.addForce(model, model.u, 0, f, nullptr);
    EXPECT_EQ(f.sum(), 1);
    EXPECT_EQ(f(3), 1);
    EXPECT_THROW(load.setForces({1, 2, 3}), SolidError);
    NodalLoad timed(nodes, 0, [](double t) { return t; });
    EXPECT_THROW(timed.setForces({1, 2, 3, 4}), SolidError);
    NodalLoad threeD(nodes, 3);
    EXPECT_THROW(threeD.addForce(model, model.u, 0, f, nullptr), SolidError);
}



TEST(SolidLoads, NodalLoadLinearInTime)
{
    // Forces linear between (f0, t0) and (f1, t1): the FSI coupling's load
    // over the solid substeps of one coupled step. f1 exactly at t1 and
    // one ulp either side of it (the last substep's end), f0 before t0
    Mesh m = Mesh::rectangle(2, 1, 0, 2, 0, 1);
    Model model(m);
    model.setMaterial("solid", solidTest::material(1, 1));
    model.initialise();
    const std::vector<int> nodes = {4, 1};
    NodalLoad load(nodes, 2);
    const std::vector<double> f0 = {1.0, -2.0, 0.3, 4.0};
    const std::vector<double> f1 = {3.0, 2.0, 0.1, -4.0};
    const double t0 = 1.1e-8, t1 = 1.1e-8 + 7.3e-11;
    load.setForces(f0, t0, f1, t1);
    EXPECT_EQ(load.forces(), f1);
    auto at = [&](double t)
    {
        Eigen::VectorXd f = Eigen::VectorXd::Zero(model.nDisplacementDofs());
        load.addForce(model, model.u, t, f, nullptr);
        return std::vector<double>{f(8), f(9), f(2), f(3)};
    };
    EXPECT_EQ(at(t0), f0);
    EXPECT_EQ(at(t0 - 1e-9), f0);
    EXPECT_EQ(at(t1), f1);
    EXPECT_EQ(at(std::nextafter(t1, 0.0)), f1);
    EXPECT_EQ(at(std::nextafter(t1, 1.0)), f1);
    EXPECT_EQ(at(t1 + 1e-9), f1);
    const std::vector<double> q = at(t0 + 0.25*(t1 - t0));
    for (int k = 0; k < 4; ++k)
    {
        EXPECT_NEAR(q[k], 0.75*f0[k] + 0.25*f1[k], 1e-12) << k;
    }
    EXPECT_THROW(load.setForces(f0, t1, f1, t0), SolidError);
    EXPECT_THROW(load.setForces(f0, t0, {1, 2}, t1), SolidError);
    // A constant load again after setForces(f)
    load.setForces(f0);
    EXPECT_EQ(at(t0 + 0.25*(t1 - t0)), f0);
}


TEST(SolidLoads, AugmentedLagrangianLoop)
{
    const double L = 1e-5;
    Mesh m = Mesh::box(1, 1, 1, Vec3(0, 0, 0), Vec3(L, L, L));
    Model model(m);
    model.setMaterial("solid", solidTest::material(100, 0));
    model.fix("xmin", 0);
    model.fix("ymin", 1);
    model.fix("zmin", 2);
    // Tie one top node to -1 % of L with a penalty of about ten times the
    // block stiffness mu L: a pure penalty misses the target by ~10 %;
    // the augmentations (Uzawa, linear rate ~ 1/11) must reach 1e-6 of it
    const int node = m.nodeSet("zmax")[0];
    const double target = -0.01*L;
    auto tie = std::make_shared<AugmentedTie>(3*node + 2, target,
                                              10*200*L, 1e-6*0.01*L);
    model.add(tie);
    model.initialise();
    StaticSolver solver(model);
    const StepReport r = solver.step(1.0);
    std::printf("augmented tie: %d augmentations, gap %.2e m\n",
                r.augmentations, model.u(3*node + 2) - target);
    EXPECT_GE(r.augmentations, 3);
    EXPECT_LE(std::abs(model.u(3*node + 2) - target), 1e-6*0.01*L);

    // The same with the penalty alone (no augmentation) misses the target
    Model plain(m);
    plain.setMaterial("solid", solidTest::material(100, 0));
    plain.fix("xmin", 0);
    plain.fix("ymin", 1);
    plain.fix("zmin", 2);
    plain.add(std::make_shared<AugmentedTie>(3*node + 2, target, 10*200*L,
                                             1e-6*0.01*L));
    plain.initialise();
    NewtonSettings ns;
    ns.maxAugmentations = 0;
    StaticSolver(plain, ns).step(1.0);
    const double gap0 = std::abs(plain.u(3*node + 2) - target);
    std::printf("penalty only: gap %.2e m (%.2f %% of the target)\n", gap0,
                100*gap0/std::abs(target));
    EXPECT_GT(gap0, 1e-3*std::abs(target));
}
