// planeWaveCell: the cell alone (solid library, no fluid) under the exact
// pressure field of a plane wave in water, to separate the solid's own
// errors from the coupling's (docs/results/blast3D.md, "The pole jet").
//
// The wave comes down from +z and is reflected by the rigid bottom z = 0;
// in linear acoustics the field is p = P(t - (z1 - z)/c) + P(t - (z1 + z)/c)
// (P the pulse: linear rise, plateau, linear fall), the particle velocity
// v_z = (P_ref - P_inc)/(rho c). The cell's materials have water's bulk
// response and shear moduli of 1e2 Pa, so in the continuum the cell is
// transparent: its motion is this 1D field, with no lateral velocity.
// On the outer surface the traction is -p n at every Gauss point; with
// -absorbing also -rho c ((v - v_1D).n) n, the characteristic condition of
// water (what the solid would radiate leaves), so that the exact answer is
// the 1D field at all times and a growing error is the solid's own.
//
// Usage: planeWaveCell cell.msh tEnd P0 rise width [-absorbing]
//          [-shearViscosity BETA [-filter]] [-textFactor4] [-vonMises]
//   [SI units; materials, fixed sets and hourglass viscosity of
//   tutorials/blast/quarter3D]. Prints per 5 ns: the rms and max of
//   v_z - v_1D over the nodes, where the max is, the largest lateral speed.
//   -shearViscosity, -filter: the deviatoric numerical viscosity as the
//   tutorial's shearViscosity, shearViscosityFilter; -textFactor4: the
//   nucleus of the tutorial's reading (C10 6.67 Pa, mu1 431.12 Pa) instead
//   of Table 2's; -vonMises: also the mean element von Mises per region
//   (exact answer after the pulse: 0; docs/results/blast3D.md, "The von
//   Mises at rest in 3D").

#include "ExplicitSolver.H"
#include "GmshReader.H"
#include "Material.H"
#include "Model.H"
#include "Shape.H"
#include "SolidError.H"
#include "StringEntries.H"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

using namespace solid;

namespace
{

const double rho = 1000, c = 1450;      // water [kg/m^3], [m/s]

struct Pulse
{
    double P0, rise, width, z1;         // [Pa], [s], [s], front at t = 0 [m]

    double at(double tau) const
    {
        if (tau <= 0) return 0;
        if (tau < rise) return P0*tau/rise;
        if (tau < width) return P0;
        if (tau < width + rise) return P0*(1 - (tau - width)/rise);
        return 0;
    }
    double incident(double z, double t) const { return at(t - (z1 - z)/c); }
    double reflected(double z, double t) const { return at(t - (z1 + z)/c); }
    double velocity(double z, double t) const
    {
        return (reflected(z, t) - incident(z, t))/(rho*c);
    }
};

class PlaneWaveLoad
:
    public Contribution
{
    Pulse w_;
    bool absorbing_;

public:

    PlaneWaveLoad(const Pulse& w, bool absorbing)
    :
        w_(w), absorbing_(absorbing)
    {}

    void addForce
    (
        const Model& model,
        const Eigen::VectorXd& u,
        double t,
        Eigen::VectorXd& f,
        Triplets*
    ) const override
    {
        const Mesh& mesh = model.mesh();
        const ShapeRule& rule = faceRule(mesh.type);
        const int nf = rule.nen;
        for (const auto& face : mesh.faceSet("outerSurface"))
        {
            for (int q = 0; q < rule.nqp(); ++q)
            {
                Vec3 x1 = Vec3::Zero(), x2 = Vec3::Zero(), v = Vec3::Zero();
                double z = 0;
                for (int a = 0; a < nf; ++a)
                {
                    const int n = face[a];
                    const Vec3 x = mesh.X[n] + u.segment<3>(3*n);
                    x1 += rule.dNdxi[q](a, 0)*x;
                    x2 += rule.dNdxi[q](a, 1)*x;
                    z += rule.N[q](a)*mesh.X[n](2);
                    v += rule.N[q](a)*model.v.segment<3>(3*n);
                }
                const Vec3 nda = x1.cross(x2)*rule.w[q];
                double p = w_.incident(z, t) + w_.reflected(z, t);
                if (absorbing_)
                {
                    const Vec3 v1(0, 0, w_.velocity(z, t));
                    p += rho*c*(v - v1).dot(nda.normalized());
                }
                for (int a = 0; a < nf; ++a)
                {
                    f.segment<3>(3*face[a]) -= p*rule.N[q](a)*nda;
                }
            }
        }
    }
};

std::map<std::string, std::string> entries
(
    std::initializer_list<std::pair<const std::string, std::string>> l
)
{
    return l;
}

} // namespace


int main(int argc, char** argv)
{
    if (argc < 6)
    {
        std::fprintf
        (
            stderr, "usage: planeWaveCell cell.msh tEnd[s] P0[Pa] rise[s] "
            "width[s] [-absorbing] [-shearViscosity BETA [-filter]] "
            "[-textFactor4] [-vonMises]\n"
        );
        return 2;
    }
    try
    {
        const double tEnd = std::atof(argv[2]);
        Pulse w{std::atof(argv[3]), std::atof(argv[4]), std::atof(argv[5]), 0};
        bool absorbing = false, filter = false, textFactor4 = false;
        bool vonMises = false;
        double beta = 0;
        for (int i = 6; i < argc; ++i)
        {
            const std::string o = argv[i];
            if (o == "-absorbing") absorbing = true;
            else if (o == "-filter") filter = true;
            else if (o == "-textFactor4") textFactor4 = true;
            else if (o == "-vonMises") vonMises = true;
            else if (o == "-shearViscosity" && i + 1 < argc)
            {
                beta = std::atof(argv[++i]);
            }
            else
            {
                std::fprintf(stderr, "planeWaveCell: unknown option %s\n",
                    argv[i]);
                return 2;
            }
        }

        Mesh mesh = readGmsh(argv[1]);
        double zTop = 0;
        for (const auto& X : mesh.X) zTop = std::max(zTop, X(2));
        w.z1 = zTop + c*1e-9;                   // at the pole at t = 1 ns

        // tutorials/blast/quarter3D/constant/solidProperties
        Model model(mesh);
        const auto water = entries
        ({
            {"volumetric", "mieGruneisen"}, {"C0", "1450"}, {"s", "1.99"},
            {"Gamma0", "0.1"}, {"Cv", "4184"}, {"T0", "293.15"}
        });
        auto with = [&](std::map<std::string, std::string> m,
                        const std::map<std::string, std::string>& more)
        {
            m.insert(more.begin(), more.end());
            return m;
        };
        const std::map<std::string, std::map<std::string, std::string>> mat
        {
            {"nucleus", with(water, entries({
                {"C10", textFactor4 ? "6.67" : "13.33"},
                {"mu1", textFactor4 ? "431.12" : "862.22"}, {"tau1", "0.5"}}))},
            {"cytoplasm", with(water, entries({{"C10", "1.67"},
                {"mu1", "107.78"}, {"tau1", "0.01"}}))},
            {"membrane", entries({{"C10", "166.67"}, {"mu1", "13.89"},
                {"tau1", "3000"}, {"volumetric", "quadratic"},
                {"d0", "9.5125e-10"}})}
        };
        for (const auto& m : mat)
        {
            model.setMaterial
            (
                m.first,
                Material::create
                (
                    MaterialParameters::fromEntries
                    (
                        m.first,
                        StringEntries("material '" + m.first + "'", m.second)
                    )
                )
            );
        }
        for (int k = 0; k < 3; ++k) model.fix("fixedBottom", k);
        model.fix("symmetryX", 0);
        model.fix("symmetryY", 1);
        model.add(std::make_shared<PlaneWaveLoad>(w, absorbing));
        model.initialise();
        model.setCornerCheck(true);

        ExplicitSettings set;
        set.safety = 0.8;
        set.hourglass = 0.1;
        set.hourglassRegions["membrane"] = 0.5;
        set.shearViscosity = beta;
        set.shearViscosityFilter = filter;
        ExplicitSolver solver(model, set);

        const double u0 = w.P0/(rho*c);
        std::printf
        (
            "planeWaveCell: %d elements, %d nodes, P0 %g Pa (particle "
            "velocity %.4g m/s), rise %g s, width %g s, %s surface\n",
            mesh.nElements(), mesh.nNodes(), w.P0, u0, w.rise, w.width,
            absorbing ? "absorbing" : "loaded (no radiation)"
        );
        for (double tw = 5e-9; tw < tEnd + 1e-15; tw += 5e-9)
        {
            solver.advanceTo(tw);
            double e2 = 0, eMax = 0, lat = 0;
            int at = 0;
            for (int a = 0; a < mesh.nNodes(); ++a)
            {
                const double e =
                    model.v(3*a + 2) - w.velocity(mesh.X[a](2), model.time);
                e2 += e*e;
                if (std::abs(e) > eMax) { eMax = std::abs(e); at = a; }
                lat = std::max(lat, std::hypot(model.v(3*a), model.v(3*a + 1)));
            }
            std::printf
            (
                "t %6.2f ns  error rms %.4e m/s  max %.4e m/s at "
                "(%.2f %.2f %.2f) um  lateral max %.4e m/s\n",
                model.time*1e9, std::sqrt(e2/mesh.nNodes()), eMax,
                mesh.X[at](0)*1e6, mesh.X[at](1)*1e6, mesh.X[at](2)*1e6, lat
            );
            if (vonMises)
            {
                const int nr = int(mesh.regionNames.size());
                std::vector<double> sum(nr, 0), cnt(nr, 0);
                for (int e = 0; e < mesh.nElements(); ++e)
                {
                    const Mat3 s = model.evaluateElement(e, 0).sigma;
                    const Mat3 d = s - s.trace()/3*Mat3::Identity();
                    sum[mesh.region[e]] +=
                        std::sqrt(1.5*(d.array()*d.array()).sum());
                    cnt[mesh.region[e]] += 1;
                }
                std::printf("    mean von Mises [Pa]:");
                for (int r = 0; r < nr; ++r)
                {
                    std::printf
                    (
                        " %s %.4g", mesh.regionNames[r].c_str(),
                        cnt[r] > 0 ? sum[r]/cnt[r] : 0.0
                    );
                }
                std::printf("\n");
            }
        }
        std::printf("planeWaveCell: %ld steps\n", solver.steps());
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "planeWaveCell: %s\n", e.what());
        return 1;
    }
    return 0;
}
