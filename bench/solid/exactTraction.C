// exactTraction: the preview's cell alone under the exact plane-wave
// traction (issue 17 item 4; docs/results/blastPlaneWave.md, "The solid
// alone under the exact traction"; not a test, tests/blast/
// exactTraction.sh runs it in CI).
//
// The cell mesh of tutorials/blast/axisymmetricPreview (constant/cell.msh
// as its Allrun writes it, r-z), the tutorial's materials (previewCell.H;
// by default the transparent cell: water's law in the membrane too, as
// bench/blast/transparentCell.sh's "water", so that the 1D plane wave is
// the exact answer everywhere), its fixed sets and its explicit settings
// (explicitSafety 0.8, hourglassViscosity 0.1, shearViscosity 0.2
// filtered). No water: on the face set outerSurface the follower pressure
// (solid::PressureLoad, setFacePressures) of the exact answer,
//
//     p_f(t) = sum_q w_q p_1D(Z_q, t) / sum_q w_q,
//
// Z_q the reference heights of N points along the face (Gauss-Legendre,
// w_q their weight times r, the ring's area element), p_1D(Z, t) the
// pressure of the 1D plane wave at the material point of reference height
// Z, read from TABLE (bench/solid/exactTraction.py writes it from the
// project's 1D Lagrangian column, neuronFsi.layeredColumn), linear in Z
// and t between its rows. In uniaxial strain a point of the surface keeps
// its r and its pressure is the 1D material point's, so the exact
// solution is u_r = 0 everywhere: any lateral strain is the solid's own
// discretisation. The pressures are set before each step for its end
// time (the explicit step evaluates the external force at t_n+1).
//
// The run starts at rest at the table's first time and ends at -end (the
// table's last time by default). Output in OUTDIR, as the coupled solver
// writes it (so that bench/blast/ballLadder.py reads both):
//   postProcessing/solidProbes/0/solidProbes.dat  every step: per probe
//       pressure, von Mises, ln J and its rate, temperature rise, then per
//       probe ln|F e_z| and its rate (solid::PointProbe: a point or a
//       ball, recovered from the probe region's elements)
//   fields/<t>.dat (with -fields)  per element at each time: region,
//       reference centroid, ln J, ln|F e_z|, the lateral strain
//       ln J - ln|F e_z|, von Mises, pressure and its bulk-viscosity part
//       q, the mean nodal radial velocity
//   exactTraction.log  the settings, the faces' height range, the interior
//       nodes by their number of elements (4 at every one of a structured
//       grid), the steps,
//       the energy balance, the largest |lateral strain| over the
//       elements at each field time and at the end.
//
// Usage:
//   exactTraction MESH TABLE OUTDIR [options]
//     MESH               a gmsh file (the cell), or block:R:H:h:KIND, a
//                        column r in [0, R], z in [0, H] [m] of elements
//                        of h (rounded to fit), one region "cytoplasm",
//                        loaded on its top and its side r = R (the exact
//                        traction: a plane wave in an unbounded body),
//                        fixed at the bottom, the axis at r = 0: KIND
//                        aligned (the structured grid), smooth (interior
//                        nodes moved by a smooth field, lines tilted up to
//                        about 20 degrees, bench/solid/planeShockColumn.H)
//                        or random (interior nodes moved by up to h/4,
//                        seed 1: irregular quadrilaterals, like gmsh's;
//                        block:R:H:h:random:F by up to F h, F in [0, 0.3])
//     -probes FILE       one probe per line: NAME REGION r z [R] (metres;
//                        R > 0 a ball probe); '#' comments
//     -end T             end time [s] (default the table's last time)
//     -law water|posed   the membrane's law (default water)
//     -hourglass K       hourglassViscosity [0, 1) (default 0.1)
//     -shearViscosity B  [0, 1) (default 0.2; 0: off)
//     -filter yes|no|region   its form (default yes)
//     -volumetric element|gaussPoints   (default element)
//     -b1 X -b2 Y        every region's linear / quadratic bulk viscosity
//                        [0, 10] (default 0.06, 1.2)
//     -oneMaterial R     every region with region R's parameters
//     -faceSamples N     points per face for p_f [1, 16] (default 4)
//     -fields T1,T2,...  times [s] of the element fields
//     -smooth N          N Laplacian sweeps over the mesh before the run:
//                        each node off the mesh's boundary, the face
//                        sets, fixedBottom, axis and the region interfaces
//                        moved to the mean of its edge neighbours
//                        (Jacobi) [0, 1000] (default 0)
//   cmake --build build --target exactTraction
#include "ExplicitSolver.H"
#include "GmshReader.H"
#include "Loads.H"
#include "MixedElement.H"
#include "PointProbe.H"
#include "SolidError.H"
#include "Tensor.H"
#include "previewCell.H"
#include "../../tests/solid/SolidTestUtils.H"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace solid;

namespace
{

struct InputError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

//- p_1D(Z, t) on a grid: heights Z (increasing) and times t (increasing)
struct Table
{
    std::vector<double> Z, t, p;    // p[k*Z.size() + j] [m, s, Pa]

    double at(int j, double alpha, int k, double beta) const
    {
        const std::size_t n = Z.size();
        const double* a = p.data() + k*n + j;
        const double* b = a + n;
        return (1 - beta)*((1 - alpha)*a[0] + alpha*a[1])
             + beta*((1 - alpha)*b[0] + alpha*b[1]);
    }
};

double number(const std::string& word, const std::string& what)
{
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(word.c_str(), &end);
    if (word.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(x))
    {
        throw InputError(what + ": '" + word + "' is not a finite number");
    }
    return x;
}

Table readTable(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw InputError("table " + path + ": cannot be read");
    Table tab;
    std::string line;
    long lineNo = 0;
    while (std::getline(in, line))
    {
        ++lineNo;
        const std::string where = path + ":" + std::to_string(lineNo);
        std::istringstream is(line);
        std::string w;
        if (!(is >> w)) continue;
        if (w[0] == '#')
        {
            // the heights: "# Z [m] z1 z2 ..."
            std::string key, unit;
            if (w == "#" && (is >> key) && key == "Z" && (is >> unit)
                && unit == "[m]")
            {
                while (is >> w) tab.Z.push_back(number(w, where));
            }
            continue;
        }
        if (tab.Z.size() < 2)
        {
            throw InputError(where + ": a data row before the heights line "
                "'# Z [m] z1 z2 ...' (at least two heights)");
        }
        tab.t.push_back(number(w, where + " (time)"));
        std::size_t n = 0;
        while (is >> w)
        {
            tab.p.push_back(number(w, where));
            ++n;
        }
        if (n != tab.Z.size())
        {
            throw InputError(where + ": " + std::to_string(n) + " pressures "
                "for " + std::to_string(tab.Z.size()) + " heights");
        }
    }
    if (tab.t.size() < 2)
    {
        throw InputError("table " + path + ": fewer than two time rows");
    }
    for (std::size_t j = 1; j < tab.Z.size(); ++j)
    {
        if (!(tab.Z[j] > tab.Z[j - 1]))
        {
            throw InputError("table " + path + ": the heights must increase "
                "(height " + std::to_string(j + 1) + ")");
        }
    }
    for (std::size_t k = 1; k < tab.t.size(); ++k)
    {
        if (!(tab.t[k] > tab.t[k - 1]))
        {
            throw InputError("table " + path + ": the times must increase "
                "(row " + std::to_string(k + 1) + ")");
        }
    }
    return tab;
}

struct ProbeSpec
{
    std::string name, region;
    double r = 0, z = 0, R = 0;
};

std::vector<ProbeSpec> readProbes(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw InputError("probes " + path + ": cannot be read");
    std::vector<ProbeSpec> out;
    std::string line;
    long lineNo = 0;
    while (std::getline(in, line))
    {
        ++lineNo;
        const std::string where = path + ":" + std::to_string(lineNo);
        const std::size_t hash = line.find('#');
        if (hash != std::string::npos) line.erase(hash);
        std::istringstream is(line);
        std::vector<std::string> w;
        std::string x;
        while (is >> x) w.push_back(x);
        if (w.empty()) continue;
        if (w.size() != 4 && w.size() != 5)
        {
            throw InputError(where + ": a probe is NAME REGION r z [R], "
                "found " + std::to_string(w.size()) + " words");
        }
        ProbeSpec p;
        p.name = w[0];
        p.region = w[1];
        p.r = number(w[2], where + " (r [m])");
        p.z = number(w[3], where + " (z [m])");
        if (w.size() == 5) p.R = number(w[4], where + " (R [m])");
        if (p.r < 0 || p.R < 0)
        {
            throw InputError(where + ": r and R must be >= 0 m");
        }
        out.push_back(p);
    }
    return out;
}

//- A bounded option value
double inRange
(
    const std::string& opt,
    const std::string& word,
    double lo,
    double hi,
    bool hiOpen
)
{
    const double x = number(word, opt);
    if (x < lo || (hiOpen ? x >= hi : x > hi))
    {
        std::ostringstream m;
        m << opt << " " << word << ": outside the valid range [" << lo
          << ", " << hi << (hiOpen ? ")" : "]");
        throw InputError(m.str());
    }
    return x;
}

//- Gauss-Legendre points and weights on [0, 1], n in [1, 16]
void gauss(int n, std::vector<double>& x, std::vector<double>& w)
{
    x.assign(n, 0);
    w.assign(n, 0);
    for (int i = 0; i < n; ++i)
    {
        double z = std::cos(M_PI*(i + 0.75)/(n + 0.5)), dp = 0;
        for (int it = 0; it < 100; ++it)
        {
            double p0 = 1, p1 = 0;
            for (int k = 1; k <= n; ++k)
            {
                const double p2 = p1;
                p1 = p0;
                p0 = ((2*k - 1)*z*p1 - (k - 1)*p2)/k;
            }
            dp = n*(z*p0 - p1)/(z*z - 1);
            const double dz = p0/dp;
            z -= dz;
            if (std::abs(dz) < 1e-15) break;
        }
        x[i] = 0.5*(1 - z);
        w[i] = 1/((1 - z*z)*dp*dp);
    }
}

std::vector<double> timeList(const std::string& s)
{
    std::vector<double> out;
    std::stringstream ss(s);
    std::string w;
    while (std::getline(ss, w, ','))
    {
        out.push_back(number(w, "-fields"));
    }
    std::sort(out.begin(), out.end());
    return out;
}

Vec3 centroid(const Mesh& m, int e)
{
    Vec3 c = Vec3::Zero();
    for (int a = 0; a < m.nen(); ++a) c += m.X[m.element(e)[a]];
    return c/m.nen();
}

//- The mesh of MESH: a gmsh file or block:R:H:h:KIND (see the usage)
Mesh buildMesh(const std::string& spec)
{
    if (spec.rfind("block:", 0) != 0) return readGmsh(spec);
    std::vector<std::string> w;
    std::stringstream ss(spec.substr(6));
    std::string x;
    while (std::getline(ss, x, ':')) w.push_back(x);
    if (w.size() != 4 && !(w.size() == 5 && w[3] == "random"))
    {
        throw InputError("mesh " + spec + ": block:R:H:h:KIND or "
            "block:R:H:h:random:FRACTION");
    }
    const double frac = w.size() == 5
        ? inRange("block random FRACTION", w[4], 0, 0.3, false) : 0.25;
    const double R = inRange("block R", w[0], 1e-9, 1e-3, false);
    const double H = inRange("block H", w[1], 1e-9, 1e-3, false);
    const double h = inRange("block h", w[2], 1e-9, 1e-3, false);
    const std::string kind = w[3];
    if (kind != "aligned" && kind != "smooth" && kind != "random")
    {
        throw InputError("mesh " + spec + ": KIND " + kind + ": aligned, "
            "smooth or random");
    }
    const int nr = std::max(1, int(std::lround(R/h)));
    const int nz = std::max(1, int(std::lround(H/h)));
    Mesh m = Mesh::rectangle(nr, nz, 0, R, 0, H);
    if (kind == "random")
    {
        solidTest::distortInterior(m, h, frac, 1);
    }
    else if (kind == "smooth")
    {
        solidTest::distortSmoothly(m, R, H);
    }
    m.regionNames[0] = "cytoplasm";
    m.nodeSets["fixedBottom"] = m.nodeSets.at("bottom");
    m.nodeSets["axis"] = m.nodeSets.at("left");
    std::vector<std::vector<int>> outer = m.faceSets.at("top");
    const auto& right = m.faceSets.at("right");
    outer.insert(outer.end(), right.begin(), right.end());
    m.faceSets["outerSurface"] = outer;
    return m;
}

//- N Jacobi sweeps of Laplacian smoothing over the free interior nodes
void smooth(Mesh& m, int sweeps)
{
    if (sweeps <= 0) return;
    const int nn = m.nNodes(), nen = m.nen();
    // fixed: the mesh's boundary (edges of one element), the face sets,
    // the fixed sets and the region interfaces (the probes' points on
    // them stay where they were)
    std::vector<bool> fixed(nn, false);
    for (const char* set : {"fixedBottom", "axis"})
    {
        const auto it = m.nodeSets.find(set);
        if (it == m.nodeSets.end()) continue;
        for (const int n : it->second) fixed[n] = true;
    }
    for (const auto& s : m.faceSets)
        for (const auto& f : s.second)
            for (const int n : f) fixed[n] = true;
    std::map<std::pair<int, int>, int> edges;
    for (int e = 0; e < m.nElements(); ++e)
    {
        const int* c = m.element(e);
        for (int a = 0; a < nen; ++a)
        {
            const int i = c[a], j = c[(a + 1) % nen];
            ++edges[{std::min(i, j), std::max(i, j)}];
        }
    }
    for (const auto& kv : edges)
    {
        if (kv.second == 1)
        {
            fixed[kv.first.first] = true;
            fixed[kv.first.second] = true;
        }
    }
    std::vector<int> region(nn, -1);
    std::vector<std::vector<int>> nb(nn);
    for (int e = 0; e < m.nElements(); ++e)
    {
        const int* c = m.element(e);
        for (int a = 0; a < nen; ++a)
        {
            const int n = c[a];
            if (region[n] >= 0 && region[n] != m.region[e]) fixed[n] = true;
            region[n] = m.region[e];
            nb[n].push_back(c[(a + 1) % nen]);
            nb[n].push_back(c[(a + nen - 1) % nen]);
        }
    }
    for (auto& v : nb)
    {
        std::sort(v.begin(), v.end());
        v.erase(std::unique(v.begin(), v.end()), v.end());
    }
    for (int it = 0; it < sweeps; ++it)
    {
        std::vector<Vec3> X = m.X;
        for (int n = 0; n < nn; ++n)
        {
            if (fixed[n] || nb[n].empty()) continue;
            Vec3 c = Vec3::Zero();
            for (const int k : nb[n]) c += m.X[k];
            X[n] = c/double(nb[n].size());
        }
        m.X = X;
    }
    m.check();
}

//- The interior nodes (on no edge of one element) by the number of
//  elements at them: counts of 3, 4, 5 and other (r-z quadrilaterals; a
//  structured grid has 4 at every one)
std::vector<int> valences(const Mesh& m)
{
    const int nen = m.nen();
    std::map<std::pair<int, int>, int> edges;
    std::vector<int> count(m.nNodes(), 0);
    for (int e = 0; e < m.nElements(); ++e)
    {
        const int* c = m.element(e);
        for (int a = 0; a < nen; ++a)
        {
            ++count[c[a]];
            const int i = c[a], j = c[(a + 1) % nen];
            ++edges[{std::min(i, j), std::max(i, j)}];
        }
    }
    std::vector<bool> boundary(m.nNodes(), false);
    for (const auto& kv : edges)
    {
        if (kv.second != 1) continue;
        boundary[kv.first.first] = true;
        boundary[kv.first.second] = true;
    }
    std::vector<int> out(4, 0);
    for (int n = 0; n < m.nNodes(); ++n)
    {
        if (boundary[n]) continue;
        ++out[count[n] >= 3 && count[n] <= 5 ? count[n] - 3 : 3];
    }
    return out;
}

//- The point nearest X on the edges of region's elements (r-z)
Vec3 nearestEdgePoint(const Mesh& m, int region, const Vec3& X)
{
    Vec3 best = X;
    double dBest = 1e300;
    for (int e = 0; e < m.nElements(); ++e)
    {
        if (m.region[e] != region) continue;
        const int* n = m.element(e);
        for (int a = 0; a < m.nen(); ++a)
        {
            const Vec3& A = m.X[n[a]];
            const Vec3& B = m.X[n[(a + 1) % m.nen()]];
            const double s = std::clamp((X - A).dot(B - A)
                /std::max((B - A).squaredNorm(), 1e-300), 0.0, 1.0);
            const Vec3 Y = A + s*(B - A);
            if ((Y - X).norm() < dBest)
            {
                dBest = (Y - X).norm();
                best = Y;
            }
        }
    }
    return best;
}

//- The largest |ln J - ln|F e_z|| over the elements, and where
struct Lateral
{
    double value = 0;
    int element = -1;
};

Lateral writeFields
(
    Model& model,
    const std::string& path,
    const std::vector<double>& depth
)
{
    const Mesh& m = model.mesh();
    std::FILE* f = path.empty() ? nullptr : std::fopen(path.c_str(), "w");
    if (!path.empty() && !f) throw InputError(path + ": cannot be written");
    if (f)
    {
        std::fprintf(f, "# t = %.9g s; per element: region, reference "
            "centroid r z [m], ln J [-], ln|F e_z| [-], lateral strain ln J "
            "- ln|F e_z| [-], von Mises [Pa], p [Pa], q [Pa] (its bulk-"
            "viscosity part), mean nodal v_r [m/s], the centroid's distance to "
            "the nearest node of outerSurface [m]\n# element region r z "
            "lnJ lnFzz lateral vonMises p q vr depth\n", model.time);
    }
    Lateral worst;
    const int dim = m.dim();
    for (int e = 0; e < m.nElements(); ++e)
    {
        const ElementOutput o = model.evaluateElement(e, 0);
        const double lnJ = std::log(o.theta);
        const double lnFzz = std::log(o.F.col(dim - 1).norm());
        const double lat = lnJ - lnFzz;
        if (std::abs(lat) > std::abs(worst.value))
        {
            worst.value = lat;
            worst.element = e;
        }
        if (!f) continue;
        double vr = 0;
        for (int a = 0; a < m.nen(); ++a)
        {
            vr += model.v(dim*m.element(e)[a])/m.nen();
        }
        const Vec3 c = centroid(m, e);
        std::fprintf(f, "%d %s %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g "
            "%.9g %.6g\n", e, m.regionNames[m.region[e]].c_str(), c(0),
            c(1), lnJ, lnFzz, lat, tensor::vonMises(o.sigma), o.p, o.q, vr,
            depth[e]);
    }
    if (f && std::fclose(f) != 0)
    {
        throw InputError(path + ": write failed");
    }
    return worst;
}

} // namespace


int main(int argc, char** argv)
{
    const std::string usage = "usage: exactTraction MESH TABLE OUTDIR "
        "[-probes FILE] [-end T] [-law water|posed] [-hourglass K] "
        "[-shearViscosity B] [-filter yes|no|region] [-volumetric "
        "element|gaussPoints] [-b1 X] [-b2 Y] [-oneMaterial REGION] "
        "[-faceSamples N] [-fields T1,T2,...] [-smooth N]";
    if (argc < 4)
    {
        std::fprintf(stderr, "%s\n", usage.c_str());
        return 1;
    }
    const std::string meshPath = argv[1], tablePath = argv[2],
        outDir = argv[3];
    try
    {
        std::string probesPath, law = "water", filter = "yes",
            volumetric = "element", oneMaterial, fieldTimes;
        ExplicitSettings set = previewCell::settings();
        double end = -1, b1 = -1, b2 = -1;
        int nSamples = 4, sweeps = 0;
        for (int i = 4; i < argc; ++i)
        {
            const std::string opt = argv[i];
            if (i + 1 >= argc)
            {
                throw InputError(opt + ": needs a value (" + usage + ")");
            }
            const std::string val = argv[++i];
            if (opt == "-probes") probesPath = val;
            else if (opt == "-end") end = inRange(opt, val, 0, 1, false);
            else if (opt == "-law") law = val;
            else if (opt == "-hourglass")
                set.hourglass = inRange(opt, val, 0, 1, true);
            else if (opt == "-shearViscosity")
                set.shearViscosity = inRange(opt, val, 0, 1, true);
            else if (opt == "-filter") filter = val;
            else if (opt == "-volumetric") volumetric = val;
            else if (opt == "-b1") b1 = inRange(opt, val, 0, 10, false);
            else if (opt == "-b2") b2 = inRange(opt, val, 0, 10, false);
            else if (opt == "-oneMaterial") oneMaterial = val;
            else if (opt == "-faceSamples")
                nSamples = int(inRange(opt, val, 1, 16, false));
            else if (opt == "-fields") fieldTimes = val;
            else if (opt == "-smooth")
                sweeps = int(inRange(opt, val, 0, 1000, false));
            else throw InputError("unknown option " + opt + " (" + usage
                + ")");
        }
        if (law != "water" && law != "posed")
        {
            throw InputError("-law " + law + ": water or posed");
        }
        if (filter != "yes" && filter != "no" && filter != "region")
        {
            throw InputError("-filter " + filter + ": yes, no or region");
        }
        if (volumetric != "element" && volumetric != "gaussPoints")
        {
            throw InputError("-volumetric " + volumetric + ": element or "
                "gaussPoints");
        }
        set.shearViscosityFilter = filter != "no" && set.shearViscosity > 0;
        set.shearViscosityFilterByRegion = filter == "region";

        const Table tab = readTable(tablePath);
        if (end < 0) end = tab.t.back();
        if (!(end > tab.t.front() && end <= tab.t.back()))
        {
            std::ostringstream m;
            m << "-end " << end << " s: outside the table's times ("
              << tab.t.front() << ", " << tab.t.back() << "] s";
            throw InputError(m.str());
        }

        Mesh built = buildMesh(meshPath);
        smooth(built, sweeps);
        Model model(std::move(built));
        const Mesh& mesh = model.mesh();
        if (!mesh.axisymmetric())
        {
            throw InputError(meshPath + ": an r-z (axisymmetric) mesh is "
                "needed (the faces' reference heights)");
        }
        // the materials: the tutorial's, or every region region R's
        std::vector<MaterialParameters> par =
        {
            previewCell::membrane(law == "water"),
            previewCell::cytoplasm(),
            previewCell::nucleus()
        };
        if (!oneMaterial.empty())
        {
            const auto it = std::find_if(par.begin(), par.end(),
                [&](const MaterialParameters& p)
                { return p.name == oneMaterial; });
            if (it == par.end())
            {
                throw InputError("-oneMaterial " + oneMaterial + ": "
                    "membrane, cytoplasm or nucleus");
            }
            const MaterialParameters one = *it;
            for (MaterialParameters& p : par)
            {
                const std::string name = p.name;
                p = one;
                p.name = name;
            }
        }
        for (MaterialParameters& p : par)
        {
            if (b1 >= 0) p.b1 = b1;
            if (b2 >= 0) p.b2 = b2;
            if (std::find(mesh.regionNames.begin(), mesh.regionNames.end(),
                p.name) == mesh.regionNames.end()) continue;
            model.setMaterial(p.name, Material::create(p));
        }
        model.fix("fixedBottom", 0);
        model.fix("fixedBottom", 1);
        model.fix("axis", 0);
        auto load = std::make_shared<PressureLoad>("outerSurface",
            [](double) { return 1.0; });
        model.add(load);
        model.setPointVolumetric(volumetric == "gaussPoints");
        model.initialise();

        // each face's samples: (height index, alpha, weight)
        const auto& faces = mesh.faceSet("outerSurface");
        std::vector<double> gx, gw;
        gauss(nSamples, gx, gw);
        struct Sample { int face, j; double alpha, w; };
        std::vector<Sample> samples;
        double zMin = 1e300, zMax = -1e300;
        for (std::size_t f = 0; f < faces.size(); ++f)
        {
            const Vec3& A = mesh.X[faces[f][0]];
            const Vec3& B = mesh.X[faces[f][1]];
            double wSum = 0;
            const std::size_t first = samples.size();
            for (int q = 0; q < nSamples; ++q)
            {
                const Vec3 X = A + gx[q]*(B - A);
                const double Z = X(1);
                zMin = std::min(zMin, Z);
                zMax = std::max(zMax, Z);
                if (Z < tab.Z.front() - 1e-12 || Z > tab.Z.back() + 1e-12)
                {
                    std::ostringstream m;
                    m << "face " << f << " of outerSurface reaches the "
                      << "height " << Z << " m, outside the table's ["
                      << tab.Z.front() << ", " << tab.Z.back() << "] m";
                    throw InputError(m.str());
                }
                const int j = std::clamp(int(std::upper_bound(tab.Z.begin(),
                    tab.Z.end(), Z) - tab.Z.begin()) - 1, 0,
                    int(tab.Z.size()) - 2);
                const double alpha = std::clamp((Z - tab.Z[j])
                    /(tab.Z[j + 1] - tab.Z[j]), 0.0, 1.0);
                // the ring's area element r ds (ds common to the face);
                // a face on the axis (r = 0 at both ends) by length
                const double w = gw[q]*std::max(X(0), 1e-30);
                samples.push_back({int(f), j, alpha, w});
                wSum += w;
            }
            for (std::size_t s = first; s < samples.size(); ++s)
            {
                samples[s].w /= wSum;
            }
        }
        std::vector<double> faceP(faces.size(), 0.0);
        // each element's depth: its centroid's distance to the nearest
        // node of the loaded surface [m]
        std::vector<double> depth(mesh.nElements(), 1e300);
        for (int e = 0; e < mesh.nElements(); ++e)
        {
            const Vec3 c = centroid(mesh, e);
            for (const auto& face : faces)
            {
                for (const int a : face)
                {
                    depth[e] = std::min(depth[e], (mesh.X[a] - c).norm());
                }
            }
        }
        const auto setPressures = [&](double t)
        {
            const int k = std::clamp(int(std::upper_bound(tab.t.begin(),
                tab.t.end(), t) - tab.t.begin()) - 1, 0,
                int(tab.t.size()) - 2);
            const double beta = std::clamp((t - tab.t[k])
                /(tab.t[k + 1] - tab.t[k]), 0.0, 1.0);
            std::fill(faceP.begin(), faceP.end(), 0.0);
            for (const Sample& s : samples)
            {
                faceP[s.face] += s.w*tab.at(s.j, s.alpha, k, beta);
            }
            load->setFacePressures(faceP);
        };

        // probes
        std::vector<ProbeSpec> specs;
        if (!probesPath.empty()) specs = readProbes(probesPath);
        std::vector<PointProbe> probes;
        for (const ProbeSpec& s : specs)
        {
            const int region = mesh.regionId(s.region);
            Vec3 X(s.r, s.z, 0);
            try
            {
                probes.emplace_back(mesh, X, region, s.R);
            }
            catch (const SolidError&)
            {
                // a point on a region's edge given to 10 digits (a coupled
                // run's header: the Fig. 10 point lies on the interface)
                // is off it by the rounding, 1e-16 m: onto the nearest
                // edge of the region's elements if within 1e-12 m
                const Vec3 Y = nearestEdgePoint(mesh, region, X);
                if ((Y - X).norm() > 1e-12) throw;
                probes.emplace_back(mesh, Y, region, s.R);
            }
        }

        namespace fs = std::filesystem;
        const fs::path out(outDir);
        fs::create_directories(out/"postProcessing"/"solidProbes"/"0");
        const std::vector<double> fTimes = timeList(fieldTimes);
        if (!fTimes.empty()) fs::create_directories(out/"fields");
        const std::string logPath = (out/"exactTraction.log").string();
        std::FILE* log = std::fopen(logPath.c_str(), "w");
        if (!log) throw InputError(logPath + ": cannot be written");
        const std::string probePath = (out/"postProcessing"/"solidProbes"
            /"0"/"solidProbes.dat").string();
        std::FILE* pf = std::fopen(probePath.c_str(), "w");
        if (!pf) throw InputError(probePath + ": cannot be written");

        const auto both = [&](const char* fmt, auto... args)
        {
            std::fprintf(log, fmt, args...);
            std::printf(fmt, args...);
        };
        both("# exactTraction %s %s %s: %d elements, %d nodes, %zu faces "
            "on outerSurface (reference heights %.6g to %.6g m), %d samples"
            " per face\n", meshPath.c_str(), tablePath.c_str(),
            outDir.c_str(), mesh.nElements(), mesh.nNodes(), faces.size(),
            zMin, zMax, nSamples);
        {
            const std::vector<int> v = valences(mesh);
            const double n = std::max(v[0] + v[1] + v[2] + v[3], 1);
            both("# interior nodes %d: at 3 / 4 / 5 / other numbers of "
                "elements %.1f / %.1f / %.1f / %.1f %%\n",
                v[0] + v[1] + v[2] + v[3], 100*v[0]/n, 100*v[1]/n,
                100*v[2]/n, 100*v[3]/n);
        }
        both("# table: %zu heights (%.6g to %.6g m), %zu times (%.6g to "
            "%.6g s); largest |p| in its first row %.3g Pa\n", tab.Z.size(),
            tab.Z.front(), tab.Z.back(), tab.t.size(), tab.t.front(),
            tab.t.back(), std::abs(*std::max_element(tab.p.begin(),
            tab.p.begin() + tab.Z.size(), [](double a, double b)
            { return std::abs(a) < std::abs(b); })));
        both("# law %s, hourglass %g, shearViscosity %g, filter %s, "
            "volumetric %s, b1 %s, b2 %s, oneMaterial %s, end %.6g s\n",
            law.c_str(), set.hourglass, set.shearViscosity,
            set.shearViscosity > 0 ? filter.c_str() : "-",
            volumetric.c_str(), b1 >= 0 ? std::to_string(b1).c_str()
            : "0.06", b2 >= 0 ? std::to_string(b2).c_str() : "1.2",
            oneMaterial.empty() ? "-" : oneMaterial.c_str(), end);

        // the coupled solver's probe file (solidDomain::setupOutput)
        const int n = int(probes.size());
        std::fprintf(pf, "# solid probes at fixed points of the reference "
            "configuration (each follows its material point), recovered "
            "from the elements of the probe's region around it: per probe "
            "pressure (+ compression), von Mises, volumetric strain ln J "
            "and its rate, temperature rise; then per probe the "
            "longitudinal strain ln|F e_z| (shock direction) and its rate"
            " (exactTraction: the solid alone under the exact traction)\n"
            "# time [s]");
        for (int i = 0; i < n; ++i)
        {
            std::fprintf(pf, "  p%d[Pa] vonMises%d[Pa] strain%d[-] "
                "strainRate%d[1/s] dT%d[K]", i, i, i, i, i);
        }
        for (int i = 0; i < n; ++i)
        {
            std::fprintf(pf, "  strainZ%d[-] strainRateZ%d[1/s]", i, i);
        }
        std::fprintf(pf, "\n");
        for (int i = 0; i < n; ++i)
        {
            const PointProbe& p = probes[i];
            std::fprintf(pf, "# probe %d %s at (%.10g %.10g %.10g) m in %s: "
                "element %d, patch of %zu elements", i, specs[i].name.c_str(),
                p.point()(0), p.point()(1), p.point()(2),
                mesh.regionNames[p.region()].c_str(), p.element(),
                p.patch().size());
            if (p.radius() > 0)
            {
                std::fprintf(pf, ": the mean over the region within radius "
                    "%.10g m of the point (%.10g m^3)", p.radius(),
                    p.volume());
            }
            std::fprintf(pf, "\n");
        }

        model.time = tab.t.front();
        setPressures(model.time);
        ExplicitSolver solver(model, set);
        std::vector<double> last(2*n, 0.0);
        std::size_t nextField = 0;
        while (nextField < fTimes.size() && fTimes[nextField] < model.time)
        {
            ++nextField;
        }
        const std::clock_t c0 = std::clock();
        while (model.time < end*(1 - 1e-12))
        {
            setPressures(model.time + solver.timeStep());
            const double h = solver.step();
            const int axial = mesh.dim() - 1;
            std::fprintf(pf, "%.10g", model.time);
            std::vector<double> ez(n);
            for (int i = 0; i < n; ++i)
            {
                const ProbeValues v = probes[i].evaluate(model);
                const double lnJ = std::log(v.theta);
                std::fprintf(pf, " %.10g %.10g %.10g %.10g %.10g", v.p,
                    tensor::vonMises(v.sigma), lnJ, (lnJ - last[2*i])/h,
                    v.temperatureRise);
                last[2*i] = lnJ;
                ez[i] = std::log(v.F.col(axial).norm());
            }
            for (int i = 0; i < n; ++i)
            {
                std::fprintf(pf, " %.10g %.10g", ez[i],
                    (ez[i] - last[2*i + 1])/h);
                last[2*i + 1] = ez[i];
            }
            std::fprintf(pf, "\n");
            while (nextField < fTimes.size()
                && model.time >= fTimes[nextField])
            {
                char name[64];
                std::snprintf(name, sizeof name, "%.4g.dat",
                    fTimes[nextField]);
                const Lateral w = writeFields(model,
                    (out/"fields"/name).string(), depth);
                both("# t = %.6g s: largest |lateral strain| %.4g (element "
                    "%d), fields/%s\n", model.time, w.value, w.element,
                    name);
                ++nextField;
            }
        }
        const double cpu = double(std::clock() - c0)/CLOCKS_PER_SEC;
        const Lateral w = writeFields(model, "", depth);
        const EnergyReport& en = solver.energy();
        both("# end t = %.6g s after %ld steps (last %.4g s), CPU %.2f s;"
            " largest |lateral strain| %.4g (element %d); energy balance "
            "%.3g of the external work %.6g J\n", model.time, solver.steps(),
            solver.timeStep(), cpu, w.value, w.element,
            en.balance()/std::max(std::abs(en.externalWork), 1e-300),
            en.externalWork);
        if (std::fclose(pf) != 0 || std::fclose(log) != 0)
        {
            throw InputError(outDir + ": a write failed");
        }
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "exactTraction: %s\n", e.what());
        return 1;
    }
    return 0;
}
