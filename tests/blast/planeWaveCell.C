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
//          [-hourglass KAPPA] [-membraneHourglass KAPPA]
//          [-table FILE] [-every DT] [-membraneWater]
//   [SI units; materials, fixed sets and hourglass viscosity of
//   tutorials/blast/quarter3D for a 3D quarter mesh, of
//   tutorials/blast/axisymmetricPreview for an r-z mesh (cellMesh mode
//   axisymmetric: fixedBottom, axis)]. Prints per 5 ns: the rms and max of
//   v_z - v_1D over the nodes, where the max is, the largest and the rms
//   lateral (radial and hoop) speed, and its rms weighted by the nodes'
//   lumped masses (comparable between r-z and 3D) (-every DT: per DT
//   instead).
//   -table FILE: the load (pressure, and the velocity of -absorbing and
//   of the error) is the exact 1D answer of the nonlinear column, tabulated
//   by bench/blast/planeWaveTable.py, at each point's current height, on
//   the table's time axis (the arguments P0 rise width then only label the
//   output): without it, the linear-acoustic pulse is exact only for small
//   P0 (at 50 MPa the Mie-Grueneisen cell's front runs ahead of it).
//   -membraneWater: the membrane with water's Mie-Grueneisen law instead
//   of its quadratic one (the whole cell volumetrically water: with
//   -table the exact answer is strictly the 1D one).
//   -hourglass, -membraneHourglass: the hourglass viscosity kappa of all
//   regions (default 0.1) and of the membrane (default 0.5 in 3D, as
//   quarter3D; the preview's kappa in r-z).
//   -shearViscosity, -filter: the deviatoric numerical viscosity as the
//   tutorial's shearViscosity, shearViscosityFilter; -textFactor4: the
//   nucleus of the tutorial's reading (C10 6.67 Pa, mu1 431.12 Pa) instead
//   of Table 2's; -vonMises: also the mean element von Mises per region
//   (exact answer after the pulse: 0; docs/results/blast3D.md, "The von
//   Mises at rest in 3D"), and the mean rz shear stress per region
//   (cylindrical components about the z axis).

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
#include <algorithm>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace solid;

namespace
{

const double rho = 1000, c = 1450;      // water [kg/m^3], [m/s]

// The exact 1D answer p(z, t), u(z, t) of the nonlinear (Mie-Grueneisen)
// column, tabulated by bench/blast/planeWaveTable.py: nz nt, the nz
// heights (uniform from 0), then per time t p(z_1..nz) u(z_1..nz);
// linear in z and t, 0 before the first time, the last time's values
// after the last
class Table
{
    int nz_ = 0, nt_ = 0;
    double dz_ = 0;
    std::vector<double> t_, p_, u_;     // p_, u_: nt x nz

public:

    explicit Table(const std::string& path)
    {
        std::FILE* f = std::fopen(path.c_str(), "r");
        if (!f) throw SolidError(SolidError::Kind::io, path + ": cannot open");
        int ch;
        while ((ch = std::fgetc(f)) == '#')
        {
            while ((ch = std::fgetc(f)) != '\n' && ch != EOF) {}
        }
        std::ungetc(ch, f);
        bool ok = std::fscanf(f, "%d %d", &nz_, &nt_) == 2 && nz_ > 1
            && nt_ > 1;
        std::vector<double> z(ok ? nz_ : 0);
        for (int k = 0; ok && k < nz_; ++k) ok = std::fscanf(f, "%lf", &z[k]) == 1;
        if (ok)
        {
            t_.resize(nt_);
            p_.resize(std::size_t(nt_)*nz_);
            u_.resize(std::size_t(nt_)*nz_);
        }
        for (int i = 0; ok && i < nt_; ++i)
        {
            ok = std::fscanf(f, "%lf", &t_[i]) == 1 && (i == 0 || t_[i] > t_[i - 1]);
            for (int k = 0; ok && k < nz_; ++k)
            {
                ok = std::fscanf(f, "%lf", &p_[std::size_t(i)*nz_ + k]) == 1;
            }
            for (int k = 0; ok && k < nz_; ++k)
            {
                ok = std::fscanf(f, "%lf", &u_[std::size_t(i)*nz_ + k]) == 1;
            }
        }
        std::fclose(f);
        if (ok)
        {
            dz_ = z[1] - z[0];
            ok = z[0] == 0 && dz_ > 0;
            for (int k = 1; ok && k < nz_; ++k)
            {
                ok = std::abs(z[k] - k*dz_) < 1e-6*dz_;
            }
        }
        if (!ok)
        {
            throw SolidError
            (
                SolidError::Kind::io, path + ": not a table of "
                "bench/blast/planeWaveTable.py (nz nt, uniform heights from "
                "0, increasing times, nt rows of 1 + 2 nz numbers)"
            );
        }
    }

    double top() const { return (nz_ - 1)*dz_; }

    //- p [Pa] and u [m/s] (upwards) at height z [m], time t [s]
    void at(double z, double t, double& p, double& u) const
    {
        if (t <= t_[0]) { p = u = 0; return; }
        int i = int(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin()) - 1;
        double a = 0;
        if (i >= nt_ - 1) i = nt_ - 2, a = 1;
        else a = (t - t_[i])/(t_[i + 1] - t_[i]);
        const double zc = std::min(std::max(z, 0.0), top());
        int k = std::min(int(zc/dz_), nz_ - 2);
        const double b = zc/dz_ - k;
        auto lin = [&](const std::vector<double>& f)
        {
            const std::size_t r0 = std::size_t(i)*nz_, r1 = r0 + nz_;
            return (1 - a)*((1 - b)*f[r0 + k] + b*f[r0 + k + 1])
                + a*((1 - b)*f[r1 + k] + b*f[r1 + k + 1]);
        };
        p = lin(p_);
        u = lin(u_);
    }
};

struct Pulse
{
    double P0, rise, width, z1;         // [Pa], [s], [s], front at t = 0 [m]
    std::shared_ptr<const Table> table; // the exact 1D answer instead

    //- Pressure [Pa] and velocity [m/s] of the 1D field at z, t: the
    //  table's, else the linear-acoustic pulse's
    void field(double z, double t, double& p, double& v) const
    {
        if (table)
        {
            table->at(z, t, p, v);
            return;
        }
        p = incident(z, t) + reflected(z, t);
        v = velocity(z, t);
    }

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
        const int dim = mesh.dim();
        for (const auto& face : mesh.faceSet("outerSurface"))
        {
            for (int q = 0; q < rule.nqp(); ++q)
            {
                Vec3 x1 = Vec3::Zero(), x2 = Vec3::Zero(), v = Vec3::Zero();
                Vec3 x = Vec3::Zero();
                double Z = 0;
                for (int a = 0; a < nf; ++a)
                {
                    const int n = face[a];
                    Vec3 xa = mesh.X[n];
                    for (int i = 0; i < dim; ++i)
                    {
                        xa(i) += u(dim*n + i);
                        v(i) += rule.N[q](a)*model.v(dim*n + i);
                    }
                    x += rule.N[q](a)*xa;
                    x1 += rule.dNdxi[q](a, 0)*xa;
                    if (dim == 3) x2 += rule.dNdxi[q](a, 1)*xa;
                    Z += rule.N[q](a)*mesh.X[n](dim - 1);
                }
                // Area vector n da (r-z: of the whole ring, the
                // orientation of solid::PressureLoad)
                const Vec3 nda = dim == 3
                  ? Vec3(x1.cross(x2)*rule.w[q])
                  : Vec3(2*M_PI*rule.w[q]*x(0)*Vec3(x1(1), -x1(0), 0));
                // The table's Eulerian field at the point's current height;
                // the acoustic pulse's at its reference height (as before)
                double p = 0;
                Vec3 v1 = Vec3::Zero();
                w_.field(w_.table ? x(dim - 1) : Z, t, p, v1(dim - 1));
                if (absorbing_)
                {
                    p += rho*c*(v - v1).dot(nda.normalized());
                }
                for (int a = 0; a < nf; ++a)
                {
                    for (int i = 0; i < dim; ++i)
                    {
                        f(dim*face[a] + i) -= p*rule.N[q](a)*nda(i);
                    }
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
            "[-textFactor4] [-vonMises] [-hourglass KAPPA] "
            "[-membraneHourglass KAPPA] [-table FILE] [-every DT] "
            "[-membraneWater]\n"
        );
        return 2;
    }
    try
    {
        const double tEnd = std::atof(argv[2]);
        Pulse w{std::atof(argv[3]), std::atof(argv[4]), std::atof(argv[5]), 0,
            nullptr};
        bool absorbing = false, filter = false, textFactor4 = false;
        bool vonMises = false, membraneWater = false;
        double beta = 0, kappa = 0.1, kappaMembrane = -1, every = 5e-9;
        for (int i = 6; i < argc; ++i)
        {
            const std::string o = argv[i];
            if (o == "-absorbing") absorbing = true;
            else if (o == "-filter") filter = true;
            else if (o == "-textFactor4") textFactor4 = true;
            else if (o == "-vonMises") vonMises = true;
            else if (o == "-membraneWater") membraneWater = true;
            else if (o == "-every" && i + 1 < argc)
            {
                every = std::atof(argv[++i]);
                if (!(every > 0))
                {
                    std::fprintf(stderr, "planeWaveCell: -every %s: a "
                        "positive interval [s]\n", argv[i]);
                    return 2;
                }
            }
            else if (o == "-table" && i + 1 < argc)
            {
                w.table = std::make_shared<const Table>(argv[++i]);
            }
            else if (o == "-hourglass" && i + 1 < argc)
            {
                kappa = std::atof(argv[++i]);
            }
            else if (o == "-membraneHourglass" && i + 1 < argc)
            {
                kappaMembrane = std::atof(argv[++i]);
            }
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
        const int dim = mesh.dim();
        double zTop = 0;
        for (const auto& X : mesh.X) zTop = std::max(zTop, X(dim - 1));
        w.z1 = zTop + c*1e-9;                   // at the pole at t = 1 ns
        if (w.table && w.table->top() < zTop + 0.2e-6)
        {
            throw SolidError
            (
                SolidError::Kind::parameter, "the table's heights end at "
              + std::to_string(w.table->top()) + " m, below the cell's top "
                "+ 0.2 um (" + std::to_string(zTop + 0.2e-6) + " m)"
            );
        }

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
            {"membrane", membraneWater
              ? with(water, entries({{"C10", "166.67"}, {"mu1", "13.89"},
                    {"tau1", "3000"}}))
              : entries({{"C10", "166.67"}, {"mu1", "13.89"},
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
        for (int k = 0; k < dim; ++k) model.fix("fixedBottom", k);
        if (dim == 3)
        {
            model.fix("symmetryX", 0);
            model.fix("symmetryY", 1);
        }
        else
        {
            model.fix("axis", 0);
        }
        model.add(std::make_shared<PlaneWaveLoad>(w, absorbing));
        model.initialise();
        model.setCornerCheck(true);

        ExplicitSettings set;
        set.safety = 0.8;
        set.hourglass = kappa;
        if (kappaMembrane < 0 && dim == 3) kappaMembrane = 0.5;
        if (kappaMembrane >= 0) set.hourglassRegions["membrane"] = kappaMembrane;
        set.shearViscosity = beta;
        set.shearViscosityFilter = filter;
        ExplicitSolver solver(model, set);

        const double u0 = w.P0/(rho*c);
        std::printf
        (
            "planeWaveCell: %d elements, %d nodes, P0 %g Pa (particle "
            "velocity %.4g m/s), rise %g s, width %g s, %s surface, %s, "
            "hourglass %g (membrane %g)\n",
            mesh.nElements(), mesh.nNodes(), w.P0, u0, w.rise, w.width,
            absorbing ? "absorbing" : "loaded (no radiation)",
            dim == 3 ? "3D" : "r-z", kappa,
            kappaMembrane >= 0 ? kappaMembrane : kappa
        );
        for (double tw = every; tw < tEnd + 1e-15; tw += every)
        {
            solver.advanceTo(tw);
            double e2 = 0, eMax = 0, lat = 0, lat2 = 0, mLat2 = 0, m = 0;
            int at = 0;
            for (int a = 0; a < mesh.nNodes(); ++a)
            {
                double pa = 0, va = 0;
                w.field
                (
                    w.table
                  ? mesh.X[a](dim - 1) + model.u(dim*a + dim - 1)
                  : mesh.X[a](dim - 1),
                    model.time, pa, va
                );
                const double e = model.v(dim*a + dim - 1) - va;
                e2 += e*e;
                if (std::abs(e) > eMax) { eMax = std::abs(e); at = a; }
                const double l = dim == 3
                  ? std::hypot(model.v(3*a), model.v(3*a + 1))
                  : std::abs(model.v(2*a));
                lat = std::max(lat, l);
                lat2 += l*l;
                mLat2 += model.lumpedMass()(dim*a)*l*l;
                m += model.lumpedMass()(dim*a);
            }
            std::printf
            (
                "t %6.2f ns  error rms %.4e m/s  max %.4e m/s at "
                "(%.2f %.2f %.2f) um  lateral max %.4e m/s  rms %.4e m/s  "
                "mass-weighted rms %.4e m/s\n",
                model.time*1e9, std::sqrt(e2/mesh.nNodes()), eMax,
                mesh.X[at](0)*1e6, mesh.X[at](1)*1e6, mesh.X[at](2)*1e6, lat,
                std::sqrt(lat2/mesh.nNodes()), std::sqrt(mLat2/m)
            );
            if (vonMises)
            {
                const int nr = int(mesh.regionNames.size());
                std::vector<double> sum(nr, 0), cnt(nr, 0), rz(nr, 0);
                const ShapeRule& vr = volumeRule(mesh.type);
                for (int e = 0; e < mesh.nElements(); ++e)
                {
                    const Mat3 s = model.evaluateElement(e, 0).sigma;
                    const Mat3 d = s - s.trace()/3*Mat3::Identity();
                    sum[mesh.region[e]] +=
                        std::sqrt(1.5*(d.array()*d.array()).sum());
                    cnt[mesh.region[e]] += 1;
                    if (dim == 2)
                    {
                        rz[mesh.region[e]] += std::abs(s(0, 1));
                        continue;
                    }
                    Vec3 xc = Vec3::Zero();
                    for (int a = 0; a < vr.nen; ++a)
                    {
                        xc += mesh.X[mesh.element(e)[a]]/vr.nen;
                    }
                    const double r = std::hypot(xc(0), xc(1));
                    if (r > 0)
                    {
                        rz[mesh.region[e]] +=
                            std::abs(xc(0)*s(0, 2) + xc(1)*s(1, 2))/r;
                    }
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
                std::printf("    mean |rz shear stress| [Pa]:");
                for (int r = 0; r < nr; ++r)
                {
                    std::printf
                    (
                        " %s %.4g", mesh.regionNames[r].c_str(),
                        cnt[r] > 0 ? rz[r]/cnt[r] : 0.0
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
