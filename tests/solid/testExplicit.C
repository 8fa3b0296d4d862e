// Explicit central-difference driver: stable time step, elastic wave
// speed in a laterally confined bar, a 50 MPa shock in a water-like
// Mie-Grueneisen column against the Hugoniot, and energy conservation.
#include "ExplicitSolver.H"
#include "Loads.H"
#include "SolidError.H"
#include "SolidTestUtils.H"

#include <gtest/gtest.h>
#include <cstdio>

using namespace solid;

namespace
{

// Column of n hexahedra (or r-z quads on the axis) of size h along z,
// lateral motion suppressed (uniaxial strain), bottom fixed
std::unique_ptr<Model> column
(
    int n, double h, std::shared_ptr<const Material> mat, bool fixTop = false,
    bool axi = false
)
{
    Mesh m = axi ? Mesh::rectangle(1, n, 0, h, 0, n*h)
                 : Mesh::box(1, 1, n, Vec3(0, 0, 0), Vec3(h, h, n*h));
    std::unique_ptr<Model> model(new Model(m));
    model->setMaterial("solid", mat);
    for (int k = 0; k < m.nNodes(); ++k)
    {
        model->fixNode(k, 0);
        if (!axi) model->fixNode(k, 1);
    }
    model->fix(axi ? "bottom" : "zmin", m.dim() - 1);
    if (fixTop) model->fix(axi ? "top" : "zmax", m.dim() - 1);
    return model;
}

// Axial velocity dof of the first node of layer k
int axialDof(const Model& m, int k)
{
    const int perLayer = m.mesh().axisymmetric() ? 2 : 4;
    return m.mesh().dim()*perLayer*k + m.mesh().dim() - 1;
}

std::shared_ptr<const Material> water(double b1, double b2)
{
    MaterialParameters p;
    p.name = "water";
    p.volumetric = "mieGruneisen";
    p.C10 = 1.67;                    // cytoplasm deviatoric part
    p.branches = {{107.78, 0.01}};
    p.b1 = b1;
    p.b2 = b2;
    return Material::create(p);
}

} // namespace


TEST(SolidExplicit, StableTimeStepFromSoundSpeed)
{
    const double h = 2e-6;
    auto model = column(10, h, water(0.06, 1.2));
    model->initialise();
    ExplicitSolver solver(*model);
    // At rest: c^2 = C0^2 + 4/3 (mu0 + mu1)/rho0, zeta = b1
    const double c = std::sqrt(1450.0*1450.0 + 4.0/3.0*(3.34 + 107.78)/1000);
    const double z = 0.06;
    EXPECT_NEAR(solver.stableTimeStep(), h/c*(std::sqrt(1 + z*z) - z),
                1e-12*h/c);
    EXPECT_NEAR(solver.timeStep(), 0.8*solver.stableTimeStep(), 1e-20);
}


TEST(SolidExplicit, ElasticBarWaveSpeed)
{
    const int n = 400;
    const double h = 5e-6, c0 = 1e6, d0 = 1e-9, rho = 1000, p0 = 1e5;
    auto model = column(n, h, solidTest::material(c0, d0, {}, rho));
    const double cd = std::sqrt((2/d0 + 4.0/3.0*2*c0)/rho);
    // Load ramped over 20 element transit times: a step front spreads
    // like t^(1/3) on the lattice and biases the half-amplitude crossing
    const double tr = 20*h/cd;
    model->add(std::make_shared<PressureLoad>("zmax",
        [=](double t) { return p0*std::min(t/tr, 1.0); }));
    model->initialise();
    ExplicitSolver solver(*model);
    const double vp = p0/(rho*cd);
    // Arrival (half the plateau velocity) at two stations
    const int k1 = 3*n/4, k2 = n/4;
    double t1 = -1, t2 = -1, vOld1 = 0, vOld2 = 0;
    while (t2 < 0 && model->time < 2e-6)
    {
        const double tOld = model->time;
        solver.step();
        const double v1 = -model->v(axialDof(*model, k1));
        const double v2 = -model->v(axialDof(*model, k2));
        auto cross = [&](double vo, double vn)
        {
            return tOld + (model->time - tOld)*(0.5*vp - vo)/(vn - vo);
        };
        if (t1 < 0 && v1 >= 0.5*vp) t1 = cross(vOld1, v1);
        if (t2 < 0 && v2 >= 0.5*vp) t2 = cross(vOld2, v2);
        vOld1 = v1;
        vOld2 = v2;
    }
    ASSERT_GT(t2, 0);
    const double c = (k1 - k2)*h/(t2 - t1);
    std::printf("bar wave speed %.2f m/s, exact %.2f m/s (rel. error "
                "%.2e), %ld steps\n", c, cd, c/cd - 1, solver.steps());
    EXPECT_NEAR(c/cd, 1.0, 1e-3);
}


TEST(SolidExplicit, MieGruneisenShockMatchesHugoniot)
{
  for (bool axi : {false, true})
  {
    const int n = 500;
    const double h = 2e-6, P = 50e6;
    auto model = column(n, h, water(0.06, 1.2), false, axi);
    model->add(std::make_shared<PressureLoad>(axi ? "top" : "zmax",
        [=](double) { return P; }));
    model->initialise();
    ExplicitSolver solver(*model);
    const eos::MieGruneisen::Parameters w;
    // Hugoniot: P = rho0 (C0 + s up) up
    const double up = (-w.C0 + std::sqrt(w.C0*w.C0 + 4*w.s*P/w.rho0))
                      /(2*w.s);
    const double Us = w.C0 + w.s*up;

    // Shock front: where the element pressure crosses P/2
    auto front = [&]()
    {
        double zPrev = 0, pPrev = 0;
        for (int e = 0; e < n; ++e)
        {
            const double p = model->evaluateElement(e, 0).p;
            const double z = (e + 0.5)*h;
            if (p < 0.5*P) { zPrev = z; pPrev = p; continue; }
            if (e == 0) return z;
            return zPrev + (z - zPrev)*(0.5*P - pPrev)/(p - pPrev);
        }
        return -1.0;
    };
    const double tA = 0.15e-6, tB = 0.45e-6;
    solver.advanceTo(tA);
    const double zA = front();
    solver.advanceTo(tB);
    const double zB = front();
    const double UsNum = (zA - zB)/(tB - tA);

    // Plateau between the loaded end and the front (10 cells margins)
    const double zTop = n*h;
    double pSum = 0, thSum = 0, dTSum = 0, vSum = 0;
    int ne = 0, nn = 0;
    for (int e = 0; e < n; ++e)
    {
        const double z = (e + 0.5)*h;
        if (z < zB + 10*h || z > zTop - 10*h) continue;
        const ElementOutput o = model->evaluateElement(e, 0);
        pSum += o.p;
        thSum += o.theta;
        dTSum += o.temperatureRise;
        ++ne;
        vSum += -model->v(axialDof(*model, e));
        ++nn;
    }
    const double pPl = pSum/ne, upPl = vSum/nn, thPl = thSum/ne,
        dT = dTSum/ne;
    const double thH = 1 - up/Us, dTH = 0.5*up*up/w.Cv;
    std::printf("%s shock: Us %.2f m/s (Hugoniot %.2f, err %.2e), plateau p "
        "%.4g Pa (err %.2e), up %.3f m/s (Hugoniot %.3f, err %.2e), 1-J "
        "%.4e (Hugoniot %.4e, err %.2e), dT %.4f K (Hugoniot %.4f)\n",
        axi ? "r-z" : "3D", UsNum, Us, UsNum/Us - 1, pPl, pPl/P - 1, upPl, up, upPl/up - 1,
        1 - thPl, 1 - thH, (1 - thPl)/(1 - thH) - 1, dT, dTH);
    EXPECT_NEAR(UsNum/Us, 1, 0.01);
    EXPECT_NEAR(pPl/P, 1, 0.01);
    EXPECT_NEAR(upPl/up, 1, 0.01);
    EXPECT_NEAR((1 - thPl)/(1 - thH), 1, 0.01);
    EXPECT_NEAR(dT/dTH, 1, 0.01);
    // Energy balance with the shock heat: KE + E_int = W_ext
    const EnergyReport& en = solver.energy();
    std::printf("shock energy: W_ext %.4e J, KE %.4e J, internal %.4e J "
        "(shock heat %.3e J), balance %.2e\n", en.externalWork, en.kinetic,
        en.internal, en.shockHeat, en.balance()/en.externalWork);
    EXPECT_LT(std::abs(en.balance()), 0.01*en.externalWork);
    EXPECT_GT(en.shockHeat, 0);
  }
}


TEST(SolidExplicit, EnergyConservedOnSmoothWave)
{
    const int n = 300;
    const double h = 5e-6;
    auto model = column(n, h, water(0, 0), true);
    model->initialise();
    // Gaussian velocity pulse in the middle
    const double zc = 0.5*n*h, wd = 15*h;
    for (int k = 0; k <= n; ++k)
    {
        const double z = k*h;
        for (int c = 0; c < 4; ++c)
        {
            model->v(axialDof(*model, k) + 3*c) =
                k == 0 || k == n ? 0 : std::exp(-std::pow((z - zc)/wd, 2));
        }
    }
    ExplicitSolver solver(*model);
    const double E0 = solver.energy().initial;
    solver.advanceTo(0.3*n*h/1450);
    const EnergyReport& en = solver.energy();
    std::printf("smooth wave: E0 %.6e J, KE %.6e J, internal %.6e J, "
        "balance %.2e, trapezoidal internal work vs material energy %.2e, "
        "%ld steps\n", E0, en.kinetic, en.internal, en.balance()/E0,
        (en.internalWork - en.internal)/E0, solver.steps());
    EXPECT_LT(std::abs(en.balance()), 0.01*E0);
    EXPECT_LT(std::abs(en.internalWork - en.internal), 0.01*E0);
    // The pulse has split: the internal energy is a real share
    EXPECT_GT(en.internal, 0.3*E0);
}


TEST(SolidExplicit, AdvanceToEqualSteps)
{
    // An interval of 3.5 stable steps: equalSteps takes 4 equal steps (the
    // default 3 full ones and a sliver of half a step); an interval within
    // one stable step is one step of the same arithmetic either way (the
    // FSI coupling's default run stays bitwise)
    const int n = 20;
    const double h = 5e-6;
    auto make = [&]()
    {
        auto model = column(n, h, water(0, 0), true);
        model->initialise();
        for (int k = 1; k < n; ++k)
        {
            for (int c = 0; c < 4; ++c)
            {
                model->v(axialDof(*model, k) + 3*c) =
                    std::sin(M_PI*k/n);
            }
        }
        return model;
    };
    auto mEq = make();
    auto mDef = make();
    ExplicitSolver eq(*mEq);
    ExplicitSolver def(*mDef);
    const double dt = eq.timeStep();
    ASSERT_EQ(dt, def.timeStep());

    // Within one step: bitwise the same state
    EXPECT_EQ(eq.advanceTo(0.7*dt, true), 1);
    EXPECT_EQ(def.advanceTo(0.7*dt), 1);
    EXPECT_EQ(mEq->time, mDef->time);
    EXPECT_EQ(mEq->u, mDef->u);
    EXPECT_EQ(mEq->v, mDef->v);
    EXPECT_EQ(eq.acceleration(), def.acceleration());

    // 3.5 stable steps from a fresh start: 4 steps, as a run of 4 fixed
    // steps of 3.5/4 of the stable step (to round-off: each step splits
    // the interval left, 3.5 dt - k h, into 4 - k) and unlike the default
    // (3 stable steps and a sliver)
    auto mEq4 = make();
    auto mDef4 = make();
    auto mRef = make();
    ExplicitSolver eq4(*mEq4);
    ExplicitSolver def4(*mDef4);
    ExplicitSettings fixed;
    fixed.fixedDt = 3.5*dt/4;
    ExplicitSolver ref(*mRef, fixed);
    const double tEnd = 3.5*dt;
    EXPECT_EQ(eq4.advanceTo(tEnd, true), 4);
    EXPECT_EQ(def4.advanceTo(tEnd), 4);
    for (int k = 0; k < 4; ++k) ref.step();
    EXPECT_NEAR(mEq4->time, tEnd, 1e-12*tEnd);
    EXPECT_NEAR(mRef->time, tEnd, 1e-12*tEnd);
    const double uScale = mRef->u.cwiseAbs().maxCoeff();
    ASSERT_GT(uScale, 0);
    EXPECT_LE((mEq4->u - mRef->u).cwiseAbs().maxCoeff(), 1e-12*uScale);
    EXPECT_LE((mEq4->v - mRef->v).cwiseAbs().maxCoeff(), 1e-12);
    // The default's sliver gives another (first-order different) answer
    EXPECT_GT((mDef4->u - mRef->u).cwiseAbs().maxCoeff(), 1e-8*uScale);
}


TEST(SolidExplicit, EnergyBalanceWithViscousDissipation)
{
    // Smooth pulse in a compressible neo-Hookean column with a Maxwell
    // branch relaxing on the time scale of the wave: KE + stored +
    // dissipated must stay equal to the initial energy
    const int n = 200;
    const double h = 5e-6, rho = 1000, c0 = 5e5, mu1 = 2e6, d0 = 2e-7;
    const double cd = std::sqrt((2/d0 + 4.0/3.0*(2*c0 + mu1))/rho);
    const double tau = 20*h/cd;
    auto model = column(n, h, solidTest::material(c0, d0, {{mu1, tau}}, rho),
                        true);
    model->initialise();
    const double zc = 0.5*n*h, wd = 15*h;
    for (int k = 1; k < n; ++k)
    {
        for (int c = 0; c < 4; ++c)
        {
            model->v(axialDof(*model, k) + 3*c) =
                std::exp(-std::pow((k*h - zc)/wd, 2));
        }
    }
    ExplicitSolver solver(*model);
    const double E0 = solver.energy().initial;
    solver.advanceTo(0.3*n*h/cd);
    const EnergyReport& en = solver.energy();
    std::printf("viscous wave: E0 %.4e J, KE %.4e, stored %.4e, dissipated "
        "%.4e (%.1f %%), balance %.2e\n", E0, en.kinetic, en.internal,
        en.dissipated, 100*en.dissipated/E0, en.balance()/E0);
    EXPECT_GT(en.dissipated, 0.02*E0);
    EXPECT_LT(std::abs(en.balance()), 0.01*E0);
}


TEST(SolidExplicit, MaxwellHeatGoesIntoEosEnergy)
{
    // Mie-Grueneisen column with a stiff Maxwell branch: the viscous
    // dissipation heats the EOS energy (adiabatic), the balance closes
    // without a separate dissipation term
    const int n = 200;
    const double h = 5e-6;
    MaterialParameters p;
    p.name = "viscousWater";
    p.volumetric = "mieGruneisen";
    p.C10 = 1e5;
    p.b1 = 0;
    p.b2 = 0;
    const double c = 1450;
    p.branches = {{2e8, 20*h/c}};
    auto model = column(n, h, Material::create(p), true);
    model->initialise();
    const double zc = 0.5*n*h, wd = 15*h;
    for (int k = 1; k < n; ++k)
    {
        for (int cc = 0; cc < 4; ++cc)
        {
            model->v(axialDof(*model, k) + 3*cc) =
                20*std::exp(-std::pow((k*h - zc)/wd, 2));
        }
    }
    ExplicitSolver solver(*model);
    const double E0 = solver.energy().initial;
    solver.advanceTo(0.3*n*h/c);
    const EnergyReport& en = solver.energy();
    const double dTmax = solver.lastAssembly().temperatureRiseMax;
    std::printf("Maxwell heat in MG: E0 %.4e J, heat %.4e J (%.1f %%), "
        "balance %.2e, max dT %.3e K\n", E0, en.viscousHeat,
        100*en.viscousHeat/E0, en.balance()/E0, dTmax);
    EXPECT_GT(en.viscousHeat, 0.01*E0);
    EXPECT_EQ(en.dissipated, 0.0);
    EXPECT_LT(std::abs(en.balance()), 0.01*E0);
    EXPECT_GT(dTmax, 0.0);
}


TEST(SolidExplicit, FreeBodyConservesMomentaAndEnergy3D)
{
    // Distorted free cube, large smooth initial velocity (shear + spin +
    // drift), neo-Hookean + Maxwell: linear and angular momentum are
    // conserved to round-off by the element forces (objectivity), energy
    // to the balance
    const double L = 1e-5;
    Mesh m = Mesh::box(4, 4, 4, Vec3(0, 0, 0), Vec3(L, L, L));
    solidTest::distortInterior(m, L/4, 0.2, 3);
    Model model(m);
    model.setMaterial("solid", solidTest::material(2e5, 1e-8,
                                                   {{1e5, 2e-9}}, 1000));
    model.initialise();
    for (int n = 0; n < m.nNodes(); ++n)
    {
        const Vec3 x = m.X[n]/L;
        model.v.segment<3>(3*n) = Vec3
        (
            3 + 20*std::sin(M_PI*x(2)) - 10*(x(1) - 0.5),
            10*(x(0) - 0.5) + 5*std::cos(M_PI*x(0)),
            -2 + 15*std::sin(M_PI*x(1))*x(0)
        );
    }
    const Eigen::VectorXd& M = model.lumpedMass();
    auto momenta = [&](Vec3& P, Vec3& H)
    {
        P.setZero();
        H.setZero();
        for (int n = 0; n < m.nNodes(); ++n)
        {
            const Vec3 x = m.X[n] + model.u.segment<3>(3*n);
            const Vec3 p = M(3*n)*model.v.segment<3>(3*n);
            P += p;
            H += x.cross(p);
        }
    };
    Vec3 P0, H0, P1, H1;
    momenta(P0, H0);
    ExplicitSolver solver(model);
    for (int i = 0; i < 300; ++i) solver.step();
    momenta(P1, H1);
    const EnergyReport& en = solver.energy();
    std::printf("free body 3D: |dP|/|P| %.1e, |dH|/|H| %.1e, energy "
        "balance %.2e of E0, dissipated %.1f %%, max displacement %.2f L\n",
        (P1 - P0).norm()/P0.norm(), (H1 - H0).norm()/H0.norm(),
        en.balance()/en.initial, 100*en.dissipated/en.initial,
        model.u.cwiseAbs().maxCoeff()/L);
    EXPECT_LT((P1 - P0).norm(), 1e-12*P0.norm());
    EXPECT_LT((H1 - H0).norm(), 1e-10*H0.norm());
    EXPECT_LT(std::abs(en.balance()), 0.01*en.initial);
    EXPECT_GT(en.dissipated, 0.005*en.initial);
}


TEST(SolidExplicit, RejectsIncompressibleRegion)
{
    auto model = column(2, 1e-6, solidTest::material(10, 0));
    model->initialise();
    try
    {
        ExplicitSolver s(*model);
        FAIL() << "no exception";
    }
    catch (const SolidError& e)
    {
        EXPECT_NE(std::string(e.what()).find("region 'solid'"),
                  std::string::npos);
        EXPECT_NE(std::string(e.what()).find("d0 = 0"), std::string::npos);
    }
}
