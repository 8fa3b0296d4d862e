// echoChain: the solid alone in 1D, a column of the 3D quarter's hexahedra
// on the rigid substrate under the exact plane-wave pressure on its top
// (docs/results/blast3D.md, "What spreads the echo in the cell (branch
// echo49)"; not a test). Which part of the solid's numerics spreads the
// substrate's echo coming up through the cell: the element size along z,
// the artificial bulk viscosity (b1, b2), the lumped mass at the scene's
// small Courant number, the filtered deviatoric viscosity.
//
// The column: one hexahedron across (H x H, slip side walls: u_x = 0 on
// x = 0, H, u_y = 0 on y = 0, H), n = round(Z/H) along z from the
// substrate (z = 0, fixed in every component, as the cell's fixedBottom)
// to the top Z, the cell's water law (Mie-Grueneisen, C0 1450 m/s, s 1.99,
// Gamma0 0.1, rho0 1000 kg/m^3) with the nucleus' shear moduli (C10 6.67
// Pa, one Maxwell branch 431.12 Pa, 0.5 s: 1e-7 of the bulk modulus, as
// the quarter's materials), solid::ExplicitSolver with the quarter's
// settings (hourglass viscosity 0.1, filtered deviatoric viscosity 0.2).
// On the top face the follower pressure (solid::PressureLoad) p_top(t):
// the 1D answer at the material point of the top's reference height,
// linear between the rows of TABLE. The 1D answer there is the incident
// wave and the substrate's echo together; the chain makes its own echo,
// so the load is exact until the chain's echo reaches its top, and what
// the chain's echo differs by is reflected there: it comes back to a
// point at height z 2 (Z - z)/c after the echo's foot, after everything
// this driver is for (the incident window and the echo's foot at the
// point).
//
// Output (OUT, text): a header with the settings and each element's
// reference centroid height, then every EVERY steps a row: time [s], the
// top's load [Pa], each element's pressure [Pa] as the coupled solver's
// probes read it (solid::Model::evaluateElement(e, 0): the equation of
// state's pressure from the committed state, without the bulk viscosity
// q).
//
// Usage:
//   echoChain TABLE OUT -h H -top Z [options]
//     TABLE              two columns: time [s], pressure [Pa] ('#' lines
//                        are comments); at least two rows, times rising;
//                        the run starts at rest at its first time (before
//                        the wave reaches the top) and ends at its last
//     -h H               element size along z and across [m], (0, Z]
//     -top Z             the column's height [m], (0, 1e-3]
//     -dt DT             fixed time step [s] (default 0: the solver's
//                        stable step x 0.8, explicitSafety); checked
//                        against the stable step
//     -b1 B1 -b2 B2      artificial bulk viscosity [0, 10] (defaults 0.06,
//                        1.2: the quarter's, solid::MaterialParameters)
//     -hourglass K       hourglassViscosity [0, 1) (default 0.1)
//     -shearViscosity B  [0, 1) (default 0.2; 0: off)
//     -filtered yes|no   its filtered form (default yes)
//     -every N           output every N steps, N >= 1 (default 1)
//     -nodes FILE        the column's node heights [m] instead of -h: one
//                        a line (or several), rising from 0 to -top (the
//                        last one is -top), each element at least 1e-8 m;
//                        the width across is the tallest element's (so
//                        that each element's characteristic length, the
//                        bulk viscosity's L, is its own height)
// Exit 1 with a message naming the option or the file on a bad input.
#include "ExplicitSolver.H"
#include "Loads.H"
#include "Material.H"
#include "SolidError.H"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{

struct Failure
{
    std::string what;
};

double number
(
    const std::string& option,
    const std::string& text,
    double lo,
    double hi,
    bool loOpen,
    bool hiOpen
)
{
    char* end = nullptr;
    const double x = std::strtod(text.c_str(), &end);
    const bool ok = !text.empty() && end && *end == '\0' && std::isfinite(x)
        && (loOpen ? x > lo : x >= lo) && (hiOpen ? x < hi : x <= hi);
    if (!ok)
    {
        std::ostringstream s;
        s << option << " " << text << ": not a number in the valid range "
          << (loOpen ? "(" : "[") << lo << ", " << hi << (hiOpen ? ")" : "]");
        throw Failure{s.str()};
    }
    return x;
}

struct Table
{
    std::vector<double> t, p;

    double operator()(double x) const
    {
        if (x <= t.front()) return p.front();
        if (x >= t.back()) return p.back();
        const auto k = std::upper_bound(t.begin(), t.end(), x) - t.begin();
        const double w = (x - t[k - 1])/(t[k] - t[k - 1]);
        return (1 - w)*p[k - 1] + w*p[k];
    }
};

Table readTable(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
    {
        throw Failure{"TABLE " + path + ": cannot be opened"};
    }
    Table tab;
    std::string line;
    int row = 0;
    while (std::getline(in, line))
    {
        ++row;
        const auto c = line.find_first_not_of(" \t\r");
        if (c == std::string::npos || line[c] == '#') continue;
        std::istringstream s(line);
        double t, p;
        std::string rest;
        if (!(s >> t >> p) || (s >> rest) || !std::isfinite(t)
         || !std::isfinite(p) || std::abs(p) > 1e10)
        {
            throw Failure
            {
                "TABLE " + path + " line " + std::to_string(row)
              + ": not two finite numbers (time [s], pressure [Pa] with "
                "|p| <= 1e10)"
            };
        }
        if (!tab.t.empty() && !(t > tab.t.back()))
        {
            throw Failure
            {
                "TABLE " + path + " line " + std::to_string(row)
              + ": the times must rise"
            };
        }
        tab.t.push_back(t);
        tab.p.push_back(p);
    }
    if (tab.t.size() < 2)
    {
        throw Failure{"TABLE " + path + ": fewer than two rows"};
    }
    return tab;
}

int run(int argc, char** argv)
{
    if (argc < 3)
    {
        throw Failure
        {
            "usage: echoChain TABLE OUT -h H -top Z [-dt DT] [-b1 B1] "
            "[-b2 B2] [-hourglass K] [-shearViscosity B] [-filtered yes|no] "
            "[-every N]"
        };
    }
    const std::string tablePath = argv[1], outPath = argv[2];
    std::map<std::string, std::string> opt;
    const std::vector<std::string> known =
    {
        "-h", "-top", "-dt", "-b1", "-b2", "-hourglass", "-shearViscosity",
        "-filtered", "-every", "-nodes"
    };
    for (int i = 3; i < argc; i += 2)
    {
        const std::string o = argv[i];
        if (std::find(known.begin(), known.end(), o) == known.end())
        {
            throw Failure{"unknown option " + o};
        }
        if (i + 1 >= argc)
        {
            throw Failure{"option " + o + " needs a value"};
        }
        if (opt.count(o))
        {
            throw Failure{"option " + o + " given twice"};
        }
        opt[o] = argv[i + 1];
    }
    if (!opt.count("-top")) throw Failure{"option -top is required"};
    if (opt.count("-h") == opt.count("-nodes"))
    {
        throw Failure{"give one of -h and -nodes"};
    }
    const double Z = number("-top", opt["-top"], 0, 1e-3, true, false);
    std::vector<double> nodes;
    if (opt.count("-nodes"))
    {
        std::ifstream in(opt["-nodes"]);
        if (!in) throw Failure{"-nodes " + opt["-nodes"]
            + ": cannot be opened"};
        std::string word;
        while (in >> word)
        {
            nodes.push_back(number("-nodes " + opt["-nodes"] + ": height",
                                   word, 0, Z, false, false));
        }
        if (nodes.size() < 2 || nodes.front() != 0
         || std::abs(nodes.back() - Z) > 1e-12*Z)
        {
            throw Failure{"-nodes " + opt["-nodes"] + ": at least two "
                "heights, the first 0 and the last -top"};
        }
        for (std::size_t k = 1; k < nodes.size(); ++k)
        {
            if (!(nodes[k] - nodes[k - 1] >= 1e-8))
            {
                throw Failure{"-nodes " + opt["-nodes"] + ": heights must "
                    "rise by at least 1e-8 m (line " + std::to_string(k + 1)
                  + ")"};
            }
        }
        nodes.back() = Z;
    }
    const double H = opt.count("-h")
        ? number("-h", opt["-h"], 0, Z, true, false) : 0;
    const double dt = opt.count("-dt")
        ? number("-dt", opt["-dt"], 0, 1e-6, false, false) : 0;
    const double b1 = opt.count("-b1")
        ? number("-b1", opt["-b1"], 0, 10, false, false) : 0.06;
    const double b2 = opt.count("-b2")
        ? number("-b2", opt["-b2"], 0, 10, false, false) : 1.2;
    const double kappa = opt.count("-hourglass")
        ? number("-hourglass", opt["-hourglass"], 0, 1, false, true) : 0.1;
    const double beta = opt.count("-shearViscosity")
        ? number("-shearViscosity", opt["-shearViscosity"], 0, 1, false, true)
        : 0.2;
    bool filtered = true;
    if (opt.count("-filtered"))
    {
        if (opt["-filtered"] != "yes" && opt["-filtered"] != "no")
        {
            throw Failure{"-filtered " + opt["-filtered"]
                + ": valid are yes and no"};
        }
        filtered = opt["-filtered"] == "yes";
    }
    const double everyX = opt.count("-every")
        ? number("-every", opt["-every"], 1, 1e6, false, false) : 1;
    const long every = std::lround(everyX);
    if (std::abs(everyX - every) > 0)
    {
        throw Failure{"-every " + opt["-every"] + ": not a whole number"};
    }
    const Table table = readTable(tablePath);

    using namespace solid;
    if (nodes.empty())
    {
        const int m = std::max(1, int(std::lround(Z/H)));
        for (int k = 0; k <= m; ++k) nodes.push_back(k*Z/m);
    }
    const int n = int(nodes.size()) - 1;
    double h = 0;
    for (int k = 0; k < n; ++k) h = std::max(h, nodes[k + 1] - nodes[k]);
    Mesh mesh = Mesh::box(1, 1, n, Vec3(0, 0, 0), Vec3(h, h, Z));
    // the uniform box's node layers moved to the given heights
    mesh.map([&nodes, n, Z](const Vec3& X)
    {
        const int k = int(std::lround(X(2)/Z*n));
        return Vec3(X(0), X(1), nodes[k]);
    });
    Model model(mesh);
    MaterialParameters par;
    par.name = "nucleus";
    par.volumetric = "mieGruneisen";
    par.C10 = 6.67;
    par.branches = {{431.12, 0.5}};
    par.b1 = b1;
    par.b2 = b2;
    model.setMaterial("solid", Material::create(par));
    model.fix("xmin", 0);
    model.fix("xmax", 0);
    model.fix("ymin", 1);
    model.fix("ymax", 1);
    for (int c = 0; c < 3; ++c) model.fix("zmin", c);
    const double t0 = table.t.front();
    model.add(std::make_shared<PressureLoad>("zmax", [&table, t0](double t)
    {
        return table(t0 + t);
    }));
    model.initialise();
    ExplicitSettings set;
    set.hourglass = kappa;
    set.shearViscosity = beta;
    set.shearViscosityFilter = filtered;
    set.fixedDt = dt;
    ExplicitSolver solver(model, set);

    std::ofstream out(outPath);
    if (!out)
    {
        throw Failure{"OUT " + outPath + ": cannot be written"};
    }
    out.precision(10);
    out << "# echoChain: " << n << " hexahedra, the tallest " << h
        << " m along z, " << h << " m across, top " << Z << " m, b1 " << b1 << ", b2 " << b2
        << ", hourglass " << kappa << ", shearViscosity " << beta
        << (filtered ? " filtered" : "") << ", dt "
        << (dt > 0 ? dt : solver.timeStep()) << " s (stable "
        << solver.stableTimeStep() << " s), table " << tablePath << "\n";
    out << "# centroids [m]:";
    for (int e = 0; e < n; ++e) out << " " << 0.5*(nodes[e] + nodes[e + 1]);
    out << "\n# time [s]  load [Pa]  p_e [Pa] (e = 0 at the substrate)\n";
    auto write = [&](double t)
    {
        out << t0 + t << " " << table(t0 + t);
        for (int e = 0; e < n; ++e)
        {
            const ElementOutput o = model.evaluateElement(e, 0);
            out << " " << o.p;
        }
        out << "\n";
    };
    write(0);
    const double tEnd = table.t.back() - t0;
    long steps = 0;
    while (model.time < tEnd*(1 - 1e-12))
    {
        solver.step();
        if (++steps % every == 0) write(model.time);
    }
    const EnergyReport& en = solver.energy();
    std::cout << "echoChain: " << n << " elements, the tallest " << h*1e6
              << " um, " << steps << " steps, energy balance "
              << en.balance()/std::max(std::abs(en.externalWork), 1e-300)
              << " of the external work\n";
    return 0;
}

} // namespace


int main(int argc, char** argv)
{
    try
    {
        return run(argc, argv);
    }
    catch (const Failure& f)
    {
        std::cerr << "echoChain: " << f.what << "\n";
        return 1;
    }
    catch (const solid::SolidError& e)
    {
        std::cerr << "echoChain: " << e.what() << "\n";
        return 1;
    }
}
