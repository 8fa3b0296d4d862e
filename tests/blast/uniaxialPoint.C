// uniaxialPoint: one material point of the solid library (solid::Material:
// neo-Hookean + Maxwell branches, the integration of Viscoelastic.H) driven
// through a uniaxial-strain history F = diag(1, 1, J(t)), as a plane wave
// carries the cell's matter. The independent check of planeWave's closed
// form (neuronFsi.planeWave.uniaxialResponse: von Mises = (mu0 + sum mu_k
// in their elastic limit) |J^2 - 1|/J^(5/3), the branches as linear
// Maxwell elements on that scalar): here the library's own second
// Piola-Kirchhoff stress, pushed forward to the Cauchy stress
// sigma = F S F^T / J, its deviator and von Mises, with each interval of
// the table cut into SUBSTEPS steps (J linear in t within it).
//
// Usage: uniaxialPoint C10 mu1 tau1 SUBSTEPS < table
//   table: rows "t J" (t [s] increasing, J > 0 [-]); C10 [Pa] (mu0 =
//   2 C10), mu1 [Pa], tau1 [s] (mu1 0: no branch).
//   Prints per row of the table: t [s], von Mises [Pa], ln J [-].
// tests/blast/uniaxialPoint.py runs it against planeWave's closed form
// (docs/results/blastPlaneWave.md, "The 5 ns von Mises").
#include "Material.H"
#include "SolidError.H"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{

double number(const char* s, const char* what)
{
    char* end = nullptr;
    const double v = std::strtod(s, &end);
    if (end == s || *end != '\0' || !std::isfinite(v))
    {
        std::fprintf(stderr, "uniaxialPoint: %s '%s': not a number\n", what,
                     s);
        std::exit(1);
    }
    return v;
}

} // namespace


int main(int argc, char** argv)
{
    if (argc != 5)
    {
        std::fprintf(stderr, "Usage: uniaxialPoint C10 mu1 tau1 SUBSTEPS "
                     "< table (rows: t [s] J [-])\n");
        return 1;
    }
    solid::MaterialParameters par;
    par.name = "point";
    par.C10 = number(argv[1], "C10");
    const double mu1 = number(argv[2], "mu1");
    const double tau1 = number(argv[3], "tau1");
    const double sub = number(argv[4], "SUBSTEPS");
    if (!(sub >= 1 && sub <= 1e6 && sub == std::floor(sub)))
    {
        std::fprintf(stderr, "uniaxialPoint: SUBSTEPS %s: a whole number "
                     "in [1, 1e6]\n", argv[4]);
        return 1;
    }
    if (mu1 != 0) par.branches.push_back({mu1, tau1});
    std::unique_ptr<solid::Material> m;
    try
    {
        m = solid::Material::create(par);
    }
    catch (const solid::SolidError& e)
    {
        std::fprintf(stderr, "uniaxialPoint: %s\n", e.what());
        return 1;
    }
    const solid::IsochoricModel& iso = m->isochoric();
    std::vector<double> hOld(iso.nHistory()), hNew(iso.nHistory());
    iso.initHistory(hOld.data());

    std::vector<double> ts, Js;
    double t, J;
    while (std::cin >> t >> J)
    {
        if (!(std::isfinite(t) && std::isfinite(J) && J > 0)
            || (!ts.empty() && !(t > ts.back())))
        {
            std::fprintf(stderr, "uniaxialPoint: row %zu (t %g s, J %g): t "
                         "must increase and J be positive\n", ts.size() + 1,
                         t, J);
            return 1;
        }
        ts.push_back(t);
        Js.push_back(J);
    }
    if (ts.empty())
    {
        std::fprintf(stderr, "uniaxialPoint: no rows on stdin\n");
        return 1;
    }
    const int n = int(sub);
    solid::IsoResponse r;
    auto vonMises = [&](double j)
    {
        const solid::Mat3 F = Eigen::Vector3d(1, 1, j).asDiagonal();
        const solid::Mat3 sigma = F*r.S*F.transpose()/j;
        const solid::Mat3 dev =
            sigma - sigma.trace()/3*solid::Mat3::Identity();
        return std::sqrt(1.5*(dev.array()*dev.array()).sum());
    };
    for (std::size_t k = 0; k < ts.size(); ++k)
    {
        if (k == 0)
        {
            const solid::Mat3 C =
                Eigen::Vector3d(1, 1, Js[0]*Js[0]).asDiagonal();
            iso.stress(C, 0.0, hOld.data(), hNew.data(), r);
            hOld = hNew;
        }
        else
        {
            const double dt = (ts[k] - ts[k - 1])/n;
            for (int i = 1; i <= n; ++i)
            {
                const double j = Js[k - 1] + (Js[k] - Js[k - 1])*i/n;
                const solid::Mat3 C = Eigen::Vector3d(1, 1, j*j).asDiagonal();
                iso.stress(C, dt, hOld.data(), hNew.data(), r);
                hOld = hNew;
            }
        }
        std::printf("%.10g %.12g %.12g\n", ts[k], vonMises(Js[k]),
                    std::log(Js[k]));
    }
    return 0;
}
