// explicitPass: the cost of the explicit solid's step on the preview's
// cell (issue 18 item 5; not a test)
//
// The cell mesh of tutorials/blast/axisymmetricPreview (constant/cell.msh
// as its Allrun writes it, e.g. `tests/blast/runPreview.sh DIR -noRun`)
// with the tutorial's solid: the materials of constant/solidProperties
// (etc/caseDicts/cellMaterials/textFactor4 and the volumetric laws given
// there: water's Mie-Grueneisen law in nucleus and cytoplasm, the
// quadratic law with d0 = 9.5125e-10 1/Pa in the membrane), its fixed
// sets, explicitSafety 0.8, hourglassViscosity 0.1, shearViscosity 0.2
// filtered. The cell starts compressed from above: v_z = -V z/z_max (V =
// 20 m/s, about a 30 MPa plane wave's particle speed), so every branch of
// the element kernel is taken (bulk viscosity in compression, Maxwell
// update, filtered shear). STEPS explicit steps, then:
//   - the stable step and the element that sets it (its region, centre,
//     characteristic length),
//   - the state's digest: u, v, fint and the histories as hexadecimal
//     floats of their sums and an FNV-1a hash of their bytes (equal
//     digests: bitwise equal arithmetic).
// Under callgrind it gives the instructions per element per step:
//   valgrind --tool=callgrind --toggle-collect='solid::ExplicitSolver::step()'
//       build/bin/explicitPass MESH 100   (one command line)
//
// Usage: explicitPass MESH [STEPS (default 100)]
//   cmake --build build --target explicitPass
#include "ExplicitSolver.H"
#include "GmshReader.H"
#include "MixedElement.H"
#include "previewCell.H"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace solid;

namespace
{

std::uint64_t fnv(const double* x, std::size_t n, std::uint64_t h)
{
    const unsigned char* c = reinterpret_cast<const unsigned char*>(x);
    for (std::size_t i = 0; i < n*sizeof(double); ++i)
    {
        h ^= c[i];
        h *= 1099511628211ull;
    }
    return h;
}

void digest(const char* name, const double* x, std::size_t n)
{
    double s = 0;
    for (std::size_t i = 0; i < n; ++i) s += x[i];
    std::printf("%-10s n %8zu sum %-24a fnv %016llx\n", name, n, s,
        (unsigned long long)fnv(x, n, 14695981039346656037ull));
}

//- The element that sets the stable step (the assembly's minimum, dt = 0:
//  zeta = b1): its step, region, centre and characteristic length
void smallestStep(Model& model, const char* when)
{
    const Mesh& mesh = model.mesh();
    int eMin = -1;
    double dtMin = 1e300, lenMin = 0;
    for (int e = 0; e < mesh.nElements(); ++e)
    {
        const ElementOutput o = model.evaluateElement(e, 0);
        const double dtE = o.length/std::sqrt(o.c2)
           *(std::sqrt(1 + o.zeta*o.zeta) - o.zeta);
        if (dtE < dtMin)
        {
            dtMin = dtE;
            eMin = e;
            lenMin = o.length;
        }
    }
    Vec3 c = Vec3::Zero();
    const int* en = mesh.element(eMin);
    for (int a = 0; a < mesh.nen(); ++a) c += mesh.X[en[a]]/mesh.nen();
    std::printf("# %s: the smallest element step %.6e s, element %d in %s "
        "at (%.3f, %.3f) um, characteristic length %.4e m\n", when, dtMin,
        eMin, mesh.regionNames[mesh.region[eMin]].c_str(), c(0)*1e6,
        c(1)*1e6, lenMin);
}

} // namespace


int main(int argc, char** argv)
{
    if (argc < 2 || argc > 3)
    {
        std::fprintf(stderr, "usage: explicitPass MESH [STEPS]\n");
        return 1;
    }
    const long steps = argc > 2 ? std::atol(argv[2]) : 100;
    if (steps < 1)
    {
        std::fprintf(stderr, "explicitPass: STEPS '%s' must be a positive "
            "integer\n", argv[2]);
        return 1;
    }
    try
    {
        Model model(readGmsh(argv[1]));
        previewCell::setUp(model);
        model.initialise();
        const Mesh& mesh = model.mesh();
        const int dim = mesh.dim();
        double zmax = 0;
        for (int n = 0; n < mesh.nNodes(); ++n)
            zmax = std::max(zmax, mesh.X[n](1));
        for (int n = 0; n < mesh.nNodes(); ++n)
            model.v(dim*n + 1) = -20.0*mesh.X[n](1)/zmax;
        for (const int d : model.prescribedDofs()) model.v(d) = 0;

        const ExplicitSettings set = previewCell::settings();
        ExplicitSolver solver(model, set);
        std::printf("# %d elements, %d nodes; stable step at start %.6e s\n",
            mesh.nElements(), mesh.nNodes(), solver.stableTimeStep());
        smallestStep(model, "at the start");
        for (long s = 0; s < steps; ++s) solver.step();
        std::printf("# after %ld steps to %.6e s: stable step %.6e s (x "
            "safety %.6e s)\n", steps, model.time, solver.stableTimeStep(),
            solver.timeStep());
        smallestStep(model, "then");

        digest("u", model.u.data(), model.u.size());
        digest("v", model.v.data(), model.v.size());
        const ExplicitState st = solver.state();
        digest("fint", st.fint.data(), st.fint.size());
        digest("fhg", st.fhg.data(), st.fhg.size());
        const StateArray& ps = model.pointState();
        const StateArray& es = model.elementState();
        const std::size_t np = ps.nItems() ? ps.current(0) - ps.current(0)
            + (ps.current(ps.nItems() - 1) - ps.current(0))
            + ps.size(ps.nItems() - 1) : 0;
        const std::size_t ne = es.nItems() ? (es.current(es.nItems() - 1)
            - es.current(0)) + es.size(es.nItems() - 1) : 0;
        digest("point", ps.current(0), np);
        digest("element", es.current(0), ne);
        std::printf("energy    balance %a internal %a kinetic %a\n",
            st.energy.balance(), st.energy.internal, st.energy.kinetic);
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "explicitPass: %s\n", e.what());
        return 1;
    }
    return 0;
}
