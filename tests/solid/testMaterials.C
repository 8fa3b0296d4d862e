// Material-point tests: tangents against finite differences, homogeneous
// analytic cases (incompressible neo-Hookean, standard linear solid with
// the paper's parameter sets, finite-strain Maxwell against an ODE),
// Mie-Grueneisen volumetric consistency and parameter validation.
#include "Material.H"
#include "NeoHookean.H"
#include "Viscoelastic.H"
#include "QuadraticVolumetric.H"
#include "MieGruneisenVolumetric.H"
#include "SolidError.H"
#include "StringEntries.H"

#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>

using namespace solid;

namespace
{

Mat3 testF()
{
    Mat3 F;
    F << 1.30, 0.25, -0.10,
         0.05, 0.85,  0.20,
        -0.15, 0.10,  1.10;
    return F;
}

// Max relative error of CC against central differences of S
double tangentError
(
    const IsochoricModel& m,
    const Mat3& C,
    double dt,
    const std::vector<double>& hOld
)
{
    std::vector<double> hNew(hOld.size() + 1);
    IsoResponse r0;
    m.evaluate(C, dt, hOld.data(), hNew.data(), r0);
    Mat6 fd;
    const double h = 1e-6;
    for (int b = 0; b < 6; ++b)
    {
        const int K = tensor::vi(b), L = tensor::vj(b);
        Mat3 dC = Mat3::Zero();
        dC(K, L) += 0.5*h;
        dC(L, K) += 0.5*h;
        IsoResponse rp, rm;
        m.evaluate(C + dC, dt, hOld.data(), hNew.data(), rp);
        m.evaluate(C - dC, dt, hOld.data(), hNew.data(), rm);
        fd.col(b) = 2*tensor::toVoigt(rp.S - rm.S)/(2*h);
    }
    return (fd - r0.CC).norm()/r0.CC.norm();
}

// Stress and energy consistency: S = 2 dPsi/dC (hyperelastic part)
double stressEnergyError(const IsochoricModel& m, const Mat3& C)
{
    IsoResponse r0;
    m.evaluate(C, 0, nullptr, nullptr, r0);
    const double h = 1e-6;
    double err = 0;
    for (int b = 0; b < 6; ++b)
    {
        const int K = tensor::vi(b), L = tensor::vj(b);
        Mat3 dC = Mat3::Zero();
        dC(K, L) += 0.5*h;
        dC(L, K) += 0.5*h;
        IsoResponse rp, rm;
        m.evaluate(C + dC, 0, nullptr, nullptr, rp);
        m.evaluate(C - dC, 0, nullptr, nullptr, rm);
        const double fd = 2*(rp.psi - rm.psi)/(2*h);
        err = std::max(err, std::abs(fd - r0.S(K, L))/r0.S.norm());
    }
    return err;
}

// Cauchy stress of the isochoric response of a material point
Mat3 cauchyIso(const IsoResponse& r, const Mat3& F)
{
    return F*r.S*F.transpose()/F.determinant();
}

struct SlsSet { const char* name; double c0, mu1, tau1; };

const SlsSet paperSets[] =
{
    {"membrane", 166.67, 13.89, 3000.0},
    {"cytoplasm", 1.67, 107.78, 0.01},
    {"nucleus", 13.33, 862.22, 0.5}
};

std::unique_ptr<Viscoelastic> sls(const SlsSet& s)
{
    return std::unique_ptr<Viscoelastic>
    (
        new Viscoelastic
        (
            std::unique_ptr<IsochoricModel>(new NeoHookean(s.c0)),
            {{s.mu1, s.tau1}}
        )
    );
}

// Drive a material point through simple shear gamma(t) on a time grid and
// return sigma_12 at the grid points
std::vector<double> shearResponse
(
    const IsochoricModel& m,
    const std::vector<double>& t,
    double (*gamma)(double, const double*),
    const double* gp
)
{
    std::vector<double> hOld(m.nHistory()), hNew(m.nHistory());
    m.initHistory(hOld.data());
    std::vector<double> s(t.size(), 0.0);
    for (std::size_t n = 1; n < t.size(); ++n)
    {
        Mat3 F = Mat3::Identity();
        F(0, 1) = gamma(t[n], gp);
        IsoResponse r;
        m.evaluate(F.transpose()*F, t[n] - t[n - 1], hOld.data(),
                   hNew.data(), r);
        hOld = hNew;
        s[n] = cauchyIso(r, F)(0, 1);
    }
    return s;
}

double rampHold(double t, const double* p)   // p = {gamma0, tRamp}
{
    return p[0]*std::min(t/p[1], 1.0);
}

double harmonic(double t, const double* p)   // p = {gamma0, omega}
{
    return p[0]*std::sin(p[1]*t);
}

// Analytic SLS shear stress for the ramp (rate gd over tr) and hold
double slsRampHold(const SlsSet& s, double g0, double tr, double t)
{
    const double mu0 = 2*s.c0, gd = g0/tr, tau = s.tau1;
    if (t <= tr)
    {
        return mu0*gd*t + s.mu1*tau*gd*(-std::expm1(-t/tau));
    }
    return mu0*g0
      + s.mu1*tau*gd*(-std::expm1(-tr/tau))*std::exp(-(t - tr)/tau);
}

} // namespace


TEST(SolidMaterial, NeoHookeanTangentAndEnergy)
{
    NeoHookean nh(166.67);
    const Mat3 F = testF();
    const Mat3 C = F.transpose()*F;
    EXPECT_LT(tangentError(nh, C, 0, {}), 1e-6);
    EXPECT_LT(stressEnergyError(nh, C), 1e-6);
    // Stress free and zero energy in the reference state
    IsoResponse r;
    nh.evaluate(Mat3::Identity(), 0, nullptr, nullptr, r);
    EXPECT_LT(r.S.norm(), 1e-12);
    EXPECT_NEAR(r.psi, 0, 1e-12);
}


TEST(SolidMaterial, ViscoelasticTangentWithHistory)
{
    for (const auto& set : paperSets)
    {
        auto m = sls(set);
        std::vector<double> h(m->nHistory());
        m->initHistory(h.data());
        // Build a non-trivial history by one step to an intermediate state
        const Mat3 F1 = Mat3::Identity() + 0.5*(testF() - Mat3::Identity());
        std::vector<double> h1(h.size());
        IsoResponse r;
        m->evaluate(F1.transpose()*F1, 0.3*set.tau1, h.data(), h1.data(), r);
        const Mat3 F = testF();
        for (double dt : {0.01*set.tau1, set.tau1, 30*set.tau1})
        {
            EXPECT_LT(tangentError(*m, F.transpose()*F, dt, h1), 1e-6)
                << set.name << " dt = " << dt;
        }
    }
}


TEST(SolidMaterial, IncompressibleNeoHookeanUniaxial)
{
    const double c0 = 166.67, mu = 2*c0;
    NeoHookean nh(c0);
    for (double lam : {0.5, 0.8, 1.2, 2.0, 3.0})
    {
        Mat3 F = Mat3::Zero();
        F(0, 0) = lam;
        F(1, 1) = F(2, 2) = 1/std::sqrt(lam);
        IsoResponse r;
        nh.evaluate(F.transpose()*F, 0, nullptr, nullptr, r);
        const Mat3 s = cauchyIso(r, F);
        // Pressure from the traction-free lateral faces
        const double p = s(1, 1);
        const double sigma = s(0, 0) - p;
        const double exact = mu*(lam*lam - 1/lam);
        EXPECT_NEAR(sigma, exact, 1e-12*std::abs(exact)) << lam;
        EXPECT_NEAR(s(2, 2) - p, 0, 1e-12*mu);
    }
}


TEST(SolidMaterial, IncompressibleNeoHookeanSimpleShear)
{
    const double c0 = 13.33, mu = 2*c0;
    NeoHookean nh(c0);
    for (double g : {0.1, 0.5, 1.0, 2.0})
    {
        Mat3 F = Mat3::Identity();
        F(0, 1) = g;
        IsoResponse r;
        nh.evaluate(F.transpose()*F, 0, nullptr, nullptr, r);
        const Mat3 s = cauchyIso(r, F);
        EXPECT_NEAR(s(0, 1), mu*g, 1e-12*mu);
        EXPECT_NEAR(s(0, 0) - s(1, 1), mu*g*g, 1e-12*mu);
        EXPECT_NEAR(s(1, 1) - s(2, 2), 0, 1e-12*mu);
        EXPECT_NEAR(s(0, 2), 0, 1e-14*mu);
    }
}


TEST(SolidMaterial, StandardLinearSolidRelaxationAndRampHold)
{
    // Small strain: the update is exact for a strain linear within each
    // step, so the remaining error is geometric, O(gamma0)
    const double g0 = 1e-6;
    for (const auto& set : paperSets)
    {
        auto m = sls(set);
        for (double trOverTau : {1e-3, 1.0})   // relaxation, ramp-and-hold
        {
            const double tr = trOverTau*set.tau1;
            std::vector<double> t{0};
            for (int i = 1; i <= 10; ++i) t.push_back(tr*i/10);
            for (int i = 1; i <= 50; ++i) t.push_back(tr + set.tau1*i/10);
            const double p[2] = {g0, tr};
            const auto s = shearResponse(*m, t, rampHold, p);
            const double peak = slsRampHold(set, g0, tr, tr);
            double err = 0;
            for (std::size_t n = 0; n < t.size(); ++n)
            {
                err = std::max
                (
                    err, std::abs(s[n] - slsRampHold(set, g0, tr, t[n]))
                );
            }
            std::printf("SLS %s tr/tau %g: rel err %.3e\n", set.name,
                        trOverTau, err/peak);
            EXPECT_LT(err/peak, 1e-5) << set.name << " tr/tau " << trOverTau;
            // Relaxed limit mu0 gamma0 after 5 tau
            EXPECT_NEAR(s.back(), 2*set.c0*g0
              + set.mu1*g0*std::exp(-5.0)*(trOverTau < 0.01 ? 1 : 0.632),
                0.01*peak);
        }
    }
}


TEST(SolidMaterial, StandardLinearSolidHarmonic)
{
    const double g0 = 1e-6;
    for (const auto& set : paperSets)
    {
        auto m = sls(set);
        const double tau = set.tau1, w = 1/tau, mu0 = 2*set.c0;
        double errPrev = 0;
        for (int nPer : {100, 200})
        {
            const double T = 2*M_PI/w;
            std::vector<double> t;
            for (int i = 0; i <= 3*nPer; ++i) t.push_back(i*T/nPer);
            const double p[2] = {g0, w};
            const auto s = shearResponse(*m, t, harmonic, p);
            // Exact: mu0 g + mu1 g0 wt/(1+w2t2) (wt sin + cos - exp(-t/tau))
            const double wt = w*tau;
            double err = 0, amp = 0;
            for (std::size_t n = 0; n < t.size(); ++n)
            {
                const double ex =
                    mu0*g0*std::sin(w*t[n])
                  + set.mu1*g0*wt/(1 + wt*wt)
                   *(wt*std::sin(w*t[n]) + std::cos(w*t[n])
                   - std::exp(-t[n]/tau));
                err = std::max(err, std::abs(s[n] - ex));
                if (n > t.size()*2/3) amp = std::max(amp, std::abs(s[n]));
            }
            // Storage and loss moduli at w tau = 1
            const double Gp = mu0 + set.mu1*wt*wt/(1 + wt*wt);
            const double Gpp = set.mu1*wt/(1 + wt*wt);
            const double ampExact = g0*std::hypot(Gp, Gpp);
            std::printf("harmonic %s n/period %d: rel err %.3e\n", set.name,
                        nPer, err/ampExact);
            EXPECT_LT(err/ampExact, 5e-4) << set.name << " " << nPer;
            EXPECT_NEAR(amp/ampExact, 1.0, 2e-3) << set.name;
            if (errPrev > 0)
            {
                const double order = std::log2(errPrev/err);
                EXPECT_GT(order, 1.8) << set.name;
                EXPECT_LT(order, 2.2) << set.name;
            }
            errPrev = err;
        }
    }
}


namespace
{

// Incompressible uniaxial Cauchy stress of the material point at stretch
// lam with the lateral faces traction free
double uniaxialSigma(const IsoResponse& r, double lam)
{
    return lam*lam*r.S(0, 0) - r.S(1, 1)/lam;
}

// Reference: RK4 on dQ/dt = -Q/tau + beta dS_iso/dlam dlam/dt for the
// principal components of the neo-Hookean branch (J = 1)
double odeRampHoldSigma
(
    double mu0, double mu1, double tau, double lamMax, double tr, double tEnd
)
{
    const double beta = mu1/mu0;
    auto lam = [&](double t) { return 1 + (lamMax - 1)*std::min(t/tr, 1.0); };
    auto lamDot = [&](double t) { return t < tr ? (lamMax - 1)/tr : 0.0; };
    auto rhs = [&](double t, const double Q[2], double dQ[2])
    {
        const double l = lam(t), ld = lamDot(t);
        dQ[0] = -Q[0]/tau + beta*mu0*2/std::pow(l, 4)*ld;
        dQ[1] = -Q[1]/tau - beta*mu0*l*l*ld;
    };
    double Q[2] = {0, 0};
    const int n = 200000;
    const double h = tEnd/n;
    for (int i = 0; i < n; ++i)
    {
        const double t = i*h;
        double k1[2], k2[2], k3[2], k4[2], y[2];
        rhs(t, Q, k1);
        for (int j = 0; j < 2; ++j) y[j] = Q[j] + 0.5*h*k1[j];
        rhs(t + 0.5*h, y, k2);
        for (int j = 0; j < 2; ++j) y[j] = Q[j] + 0.5*h*k2[j];
        rhs(t + 0.5*h, y, k3);
        for (int j = 0; j < 2; ++j) y[j] = Q[j] + h*k3[j];
        rhs(t + h, y, k4);
        for (int j = 0; j < 2; ++j)
        {
            Q[j] += h/6*(k1[j] + 2*k2[j] + 2*k3[j] + k4[j]);
        }
    }
    const double l = lam(tEnd);
    const double I1 = l*l + 2/l;
    const double S1 = mu0*(1 - I1/(3*l*l)) + Q[0];
    const double S2 = mu0*(1 - I1*l/3) + Q[1];
    return l*l*S1 - S2/l;
}

double simoRampHold
(
    const IsochoricModel& m, double lamMax, double tr, double tEnd, int nRamp,
    int nHold
)
{
    std::vector<double> hOld(m.nHistory()), hNew(m.nHistory());
    m.initHistory(hOld.data());
    IsoResponse r;
    double t = 0, l = 1;
    for (int i = 1; i <= nRamp + nHold; ++i)
    {
        const double tn = i <= nRamp ? tr*i/nRamp
                                     : tr + (tEnd - tr)*(i - nRamp)/nHold;
        l = 1 + (lamMax - 1)*std::min(tn/tr, 1.0);
        const Mat3 C = Eigen::Vector3d(l*l, 1/l, 1/l).asDiagonal();
        m.evaluate(C, tn - t, hOld.data(), hNew.data(), r);
        hOld = hNew;
        t = tn;
    }
    return uniaxialSigma(r, l);
}

} // namespace


TEST(SolidMaterial, FiniteStrainSimoRampHoldAgainstOde)
{
    // Nucleus set, stretch 1.5, ramp over tau, checked at the end of the
    // ramp and after holding 2 tau
    const SlsSet& set = paperSets[2];
    auto m = sls(set);
    const double tau = set.tau1, tr = tau;
    for (double tEnd : {tr, 3*tau})
    {
        const double ref =
            odeRampHoldSigma(2*set.c0, set.mu1, tau, 1.5, tr, tEnd);
        const int nHold = tEnd > tr ? 20 : 0;
        const double e1 = std::abs(simoRampHold(*m, 1.5, tr, tEnd, 20, nHold)
                                   - ref)/std::abs(ref);
        const double e2 = std::abs(simoRampHold(*m, 1.5, tr, tEnd, 40,
                                   2*nHold) - ref)/std::abs(ref);
        std::printf("Simo ramp-hold t = %g s: rel err %.3e (20 steps), "
                    "%.3e (40 steps)\n", tEnd, e1, e2);
        EXPECT_LT(e2, 1e-3) << "tEnd " << tEnd;
        const double order = std::log2(e1/e2);
        EXPECT_GT(order, 1.8) << "tEnd " << tEnd << " e1 " << e1;
        EXPECT_LT(order, 2.3) << "tEnd " << tEnd << " e1 " << e1;
    }
}


TEST(SolidMaterial, FastAndSlowRampLimits)
{
    for (const auto& set : paperSets)
    {
        auto m = sls(set);
        const double lam = 1.3, mu0 = 2*set.c0, mu1 = set.mu1;
        const double nh = lam*lam - 1/lam;
        const double fast = simoRampHold(*m, lam, 1e-5*set.tau1,
                                         1e-5*set.tau1, 50, 0);
        EXPECT_NEAR(fast/((mu0 + mu1)*nh), 1.0, 1e-4) << set.name;
        const double slow = simoRampHold(*m, lam, 1e5*set.tau1,
                                         1e5*set.tau1, 50, 0);
        EXPECT_NEAR(slow/(mu0*nh), 1.0, 1e-3*(1 + mu1/mu0)) << set.name;
    }
}


TEST(SolidMaterial, MieGruneisenVolumetricConsistency)
{
    eos::MieGruneisen::Parameters w;
    MieGruneisenVolumetric mg(w, 0.06, 1.2, "water");
    std::vector<double> h0(mg.nHistory()), h1(mg.nHistory());
    mg.initHistory(h0.data());
    // A first compressive step to get a non-trivial history
    VolumetricInput in{0.98, 1e-9, 1e-6};
    mg.evaluate(in, h0.data(), h1.data());
    for (double theta : {0.96, 0.985, 1.01})
    {
        VolumetricInput a{theta, 1e-9, 1e-6};
        std::vector<double> hn(mg.nHistory());
        const auto r = mg.evaluate(a, h1.data(), hn.data());
        const double d = 1e-7;
        a.theta = theta + d;
        const double pp = mg.evaluate(a, h1.data(), hn.data()).p;
        a.theta = theta - d;
        const double pm = mg.evaluate(a, h1.data(), hn.data()).p;
        EXPECT_NEAR(r.dpdtheta, (pp - pm)/(2*d), 1e-6*std::abs(r.dpdtheta))
            << theta;
    }
    // Slow adiabatic compression without viscosity follows the isentrope:
    // the EOS sound speed is dp/drho along it, and the energy is the
    // pdV work
    MieGruneisenVolumetric mg0(w, 0, 0, "water");
    std::vector<double> h(mg0.nHistory()), hn(mg0.nHistory());
    mg0.initHistory(h.data());
    double work = 0, pOld = 0;
    VolumetricResponse r;
    const int n = 4000;
    for (int i = 1; i <= n; ++i)
    {
        VolumetricInput a{1 - 0.05*i/n, 1e-6, 1e-6};
        r = mg0.evaluate(a, h.data(), hn.data());
        work += 0.5*(pOld + r.p)*0.05/n;
        pOld = r.p;
        h = hn;
    }
    EXPECT_NEAR(r.energy, work, 1e-10*work);
    VolumetricInput a{0.95, 1e-6, 1e-6};
    const double c2 = r.c2;
    const double dpdrhoS = -r.dpdtheta*0.95*0.95/w.rho0;
    EXPECT_NEAR(dpdrhoS, c2, 1e-6*c2);
    (void)a;
}


TEST(SolidMaterial, MieGruneisenAdiabaticHeating)
{
    // Heat at fixed volume: e += heat/rho0, T += heat/(rho0 Cv),
    // p += Gamma0 heat
    eos::MieGruneisen::Parameters w;
    MieGruneisenVolumetric mg(w, 0, 0, "water");
    std::vector<double> h(mg.nHistory()), hn(mg.nHistory());
    mg.initHistory(h.data());
    VolumetricInput a{0.99, 1e-9, 1e-6};
    const auto r0 = mg.evaluate(a, h.data(), hn.data());
    h = hn;
    VolumetricInput b{0.99, 1e-9, 1e-6, 4.184e6};    // 1 K of water
    const auto r1 = mg.evaluate(b, h.data(), hn.data());
    EXPECT_NEAR(r1.temperatureRise - r0.temperatureRise, 1.0, 1e-12);
    EXPECT_NEAR(r1.p - r0.p, w.Gamma0*4.184e6, 1e-6);
    EXPECT_NEAR(r1.energy - r0.energy, 4.184e6, 1e-6);
}


TEST(SolidMaterial, QuadraticVolumetric)
{
    QuadraticVolumetric q(1e-3, 1000, "test");
    VolumetricInput in{0.9, 0, 0};
    const auto r = q.evaluate(in, nullptr, nullptr);
    EXPECT_DOUBLE_EQ(r.p, 200.0);
    EXPECT_DOUBLE_EQ(r.energy, 0.01/1e-3);
    EXPECT_DOUBLE_EQ(r.dpdtheta, -2000.0);
}


namespace
{

std::string errorOf(const std::map<std::string, std::string>& e)
{
    try
    {
        MaterialParameters::fromEntries
        (
            "cytoplasm", StringEntries("material 'cytoplasm'", e)
        );
    }
    catch (const SolidError& err)
    {
        EXPECT_EQ(err.kind(), SolidError::Kind::parameter);
        return err.what();
    }
    return "";
}

} // namespace


TEST(SolidMaterial, ParameterEntriesAndValidation)
{
    // The Usage example of Material.H
    const auto p = MaterialParameters::fromEntries
    (
        "membrane",
        StringEntries
        (
            "material 'membrane'",
            {{"rho0", "1000"}, {"C10", "166.67"},
             {"volumetric", "quadratic"}, {"d0", "0"}, {"mu1", "13.89"},
             {"eta1", "41670"}}
        )
    );
    ASSERT_EQ(p.branches.size(), 1u);
    EXPECT_NEAR(p.branches[0].tau, 41670/13.89, 1e-9);
    auto m = Material::create(p);
    EXPECT_TRUE(m->volumetric().isConstraint());
    EXPECT_NEAR(m->isochoric().instantaneousShearModulus(),
                2*166.67 + 13.89, 1e-12);

    EXPECT_NE(errorOf({{"C10", "-1"}}).find("'C10' = -1"), std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"mu1", "1"}, {"tau1", "0"}})
              .find("'tau1' = 0"), std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"mu1", "1"}, {"tau1", "-2"}})
              .find("cytoplasm"), std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"mu1", "1"}})
              .find("'tau1'"), std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"d0", "-1e-3"}}).find("'d0'"),
              std::string::npos);
    // nan, inf: not a number, with the entry's valid range (adv42 g25: d0,
    // C0, Gamma0 gave none); an entry the law does not read: none
    const std::map<std::string, std::string> water
    {
        {"rho0", "1000"}, {"C10", "1"}, {"volumetric", "mieGruneisen"},
        {"C0", "1450"}, {"s", "1.99"}, {"Gamma0", "0.1"}, {"Cv", "4184"},
        {"T0", "293.15"}
    };
    for (const char* key : {"C0", "Gamma0", "s", "Cv", "T0", "rho0", "C10"})
    {
        for (const char* bad : {"nan", "inf", "soft"})
        {
            auto e = water;
            e[key] = bad;
            const std::string what(errorOf(e));
            EXPECT_NE
            (
                what.find
                (
                    "entry '" + std::string(key) + "' = '" + bad
                  + "' is not a number; valid range "
                ),
                std::string::npos
            ) << what;
            EXPECT_EQ(what.find("e+308"), std::string::npos) << what;
        }
    }
    auto eNan = water;
    eNan["Gamma0"] = "nan";
    EXPECT_NE(errorOf(eNan).find("valid range (0, 10) -"), std::string::npos)
        << errorOf(eNan);
    EXPECT_NE
    (
        errorOf({{"C10", "1"}, {"volumetric", "quadratic"}, {"d0", "inf"}})
       .find("entry 'd0' = 'inf' is not a number; valid range [0, "),
        std::string::npos
    ) << errorOf({{"C10", "1"}, {"volumetric", "quadratic"}, {"d0", "inf"}});
    eNan = water;
    eNan["d0"] = "nan";     // not read by mieGruneisen: no range
    EXPECT_NE(errorOf(eNan).find("entry 'd0' = 'nan' is not a number"),
              std::string::npos) << errorOf(eNan);
    EXPECT_EQ(errorOf(eNan).find("valid range"), std::string::npos);
    // finite but beyond the physical bounds (physicalBounds.H; issue 19,
    // adv30 sp18b, hg01, hg02: a floating-point exception in the run)
    EXPECT_NE(errorOf({{"C10", "1e300"}}).find("'C10' = 1e+300 Pa is "
              "outside the valid range [0, 1e+13)"), std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"d0", "1e300"}})
              .find("'d0' = 1e+300"), std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"d0", "1e-300"}})
              .find("'d0' = 1e-300"), std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"mu1", "1e300"}, {"tau1", "1"}})
              .find("'mu1' = 1e+300"), std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"mu1", "1"}, {"tau1", "1e300"}})
              .find("'tau1' = 1e+300"), std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"mu1", "1"}, {"eta1", "1e300"}})
              .find("'eta1' = 1e+300"), std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"rho0", "1e300"}})
              .find("'rho0' = 1e+300"), std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"volumetric", "mieGruneisen"},
                       {"C0", "1e200"}, {"s", "1.99"}, {"Gamma0", "0.1"},
                       {"Cv", "4184"}, {"T0", "293.15"}})
              .find("C0 = 1e+200"), std::string::npos);
    EXPECT_NE(errorOf({{"cO", "1"}}).find("unknown entry 'cO'"),
              std::string::npos);
    // the closest valid name (issue 19), a branch's with its number
    EXPECT_NE(errorOf({{"C10", "1"}, {"mu1", "1"}, {"tua1", "1"}})
              .find("unknown entry 'tua1'; did you mean 'tau1'?"),
              std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"Gama0", "1"}})
              .find("did you mean 'Gamma0'?"), std::string::npos);
    EXPECT_EQ(errorOf({{"C10", "1"}, {"colour", "1"}}).find("did you mean"),
              std::string::npos);
    EXPECT_NE(errorOf({{"C10", "abc"}}).find("not a number"),
              std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"volumetric", "foo"}})
              .find("valid: quadratic mieGruneisen"), std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"volumetric", "mieGruneisen"},
                       {"s", "-1"}}).find("s = "), std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"mu2", "1"}, {"tau2", "1"}})
              .find("without gaps"), std::string::npos);
    // volumetric mieGruneisen needs all of its coefficients (issue 19:
    // a missing one was water's default, silently)
    const std::map<std::string, std::string> mg =
        {{"C10", "1"}, {"volumetric", "mieGruneisen"}, {"C0", "1450"},
         {"s", "1.99"}, {"Gamma0", "0.1"}, {"Cv", "4184"}, {"T0", "293.15"}};
    EXPECT_EQ(errorOf(mg), "");
    for (const char* key : {"C0", "s", "Gamma0", "Cv", "T0"})
    {
        auto e = mg;
        e.erase(key);
        EXPECT_NE(errorOf(e).find(std::string("missing: ") + key),
                  std::string::npos) << key;
    }
    EXPECT_NE(errorOf({{"C10", "1"}, {"volumetric", "mieGruneisen"}})
              .find("missing: C0 s Gamma0 Cv T0"), std::string::npos);

    // The former names say what replaced them
    EXPECT_NE(errorOf({{"c0", "1"}}).find("entry 'c0' is now 'C10'"),
              std::string::npos);
    EXPECT_NE(errorOf({{"C10", "1"}, {"volumetric", "neoHookean"}})
              .find("'neoHookean' is now 'quadratic'"), std::string::npos);
}
