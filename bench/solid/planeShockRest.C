// planeShockRest: does the explicit Q1/P0 solid return to rest after a
// plane shock has passed? (issue 17 items 5 and 6; not a test)
//
// A column of water-like cell material (Mie-Grueneisen, cytoplasm shear
// moduli: 1e-7 of the bulk modulus), r in [0, 10] um (r-z) or x in
// [0, 10] um (a 3D slab), z in [0, 40] um, slip side walls, fixed bottom,
// 50 MPa for 5 ns (0.1 ns ramps) on the top face. The exact answer is the
// 1D plane wave: uniaxial strain while the pulse passes, and rest (zero
// strain up to the shock's entropy, ~1e-6) once it has passed and before
// its echo returns. Measured at t = 24 ns over the elements with
// centroids in z in [20, 30] um (passed by ~21 ns, the echo back at
// ~41 ns): the largest |ln stretch_z| and von Mises, for meshes
//   aligned   the structured grid
//   smooth    its interior nodes moved by a smooth field (mesh lines
//             tilted by up to about 20 degrees)
//   random    its interior nodes moved randomly by up to h/4 (irregular
//             quads, like an unstructured mesh's)
// element sizes h and hourglass viscosities kappa.
//
// Usage: planeShockRest [h1 h2 ...]   (default 0.5e-6 0.25e-6)
//   cmake --build build --target planeShockRest && build/bin/planeShockRest
#include "ExplicitSolver.H"
#include "Loads.H"
#include "Material.H"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using namespace solid;

namespace
{

struct Result { double strain, vonMises; };

Result run(double h, const std::string& mesh, double kappa)
{
    const double R = 10e-6, Z = 40e-6, P = 50e6, tp = 5e-9, tr = 0.1e-9;
    const int nr = int(std::lround(R/h)), nz = int(std::lround(Z/h));
    Mesh m = Mesh::rectangle(nr, nz, 0, R, 0, Z);
    if (mesh != "aligned")
    {
        std::vector<bool> onSet(m.nNodes(), false);
        for (const auto& s : m.nodeSets)
            for (int n : s.second) onSet[n] = true;
        std::mt19937 gen(1);
        std::uniform_real_distribution<double> d(-0.25*h, 0.25*h);
        for (int n = 0; n < m.nNodes(); ++n)
        {
            if (onSet[n]) continue;
            Vec3& X = m.X[n];
            if (mesh == "random")
            {
                X(0) += d(gen);
                X(1) += d(gen);
            }
            else
            {
                X(1) += 0.36*(X(0) - 0.5*R)*std::sin(M_PI*X(1)/Z)
                       *std::sin(M_PI*X(0)/R);
            }
        }
    }
    Model model(m);
    MaterialParameters p;
    p.name = "solid";
    p.volumetric = "mieGruneisen";
    p.C10 = 1.67;
    p.branches = {{107.78, 0.01}};
    model.setMaterial("solid", Material::create(p));
    model.fix("left", 0);
    model.fix("right", 0);
    model.fix("bottom", 1);
    model.add(std::make_shared<PressureLoad>("top", [=](double t)
    {
        if (t < tr) return P*t/tr;
        if (t < tp - tr) return P;
        if (t < tp) return P*(tp - t)/tr;
        return 0.0;
    }));
    model.initialise();
    ExplicitSettings set;
    set.hourglass = kappa;
    ExplicitSolver solver(model, set);
    solver.advanceTo(24e-9);
    Result r{0, 0};
    for (int e = 0; e < m.nElements(); ++e)
    {
        Vec3 c = Vec3::Zero();
        for (int k = 0; k < m.nen(); ++k) c += m.X[m.element(e)[k]];
        c /= m.nen();
        if (c(1) < 20e-6 || c(1) > 30e-6) continue;
        const ElementOutput o = model.evaluateElement(e, 0);
        const Mat3 s = o.sigma - o.sigma.trace()/3*Mat3::Identity();
        r.strain = std::max(r.strain, std::abs(std::log(o.F.col(1).norm())));
        r.vonMises = std::max
        (
            r.vonMises, std::sqrt(1.5*(s.array()*s.array()).sum())
        );
    }
    return r;
}

} // namespace


int main(int argc, char** argv)
{
    std::vector<double> hs;
    for (int i = 1; i < argc; ++i) hs.push_back(std::atof(argv[i]));
    if (hs.empty()) hs = {0.5e-6, 0.25e-6};
    std::printf("# plane shock (50 MPa, 5 ns) through an r-z column of cell "
        "material; at 24 ns, elements in z = [20, 30] um (passed by the "
        "pulse, before its echo): largest |ln stretch_z| [-] and von Mises "
        "[Pa]; the exact answer: 0 and 0 (peak while passing: strain "
        "0.022, von Mises 5.2 Pa)\n");
    std::printf("%-8s %8s %7s %14s %14s\n", "mesh", "h[um]", "kappa",
        "strain[-]", "vonMises[Pa]");
    for (const char* mesh : {"aligned", "smooth", "random"})
    {
        for (const double h : hs)
        {
            for (const double kappa : {0.0, 0.05, 0.1, 0.2})
            {
                const Result r = run(h, mesh, kappa);
                std::printf("%-8s %8.3g %7.3g %14.3e %14.3g\n", mesh, h*1e6,
                    kappa, r.strain, r.vonMises);
                std::fflush(stdout);
            }
        }
    }
}
