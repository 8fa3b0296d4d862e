// Micro benchmark of the solid library (not a test):
//  - implicit: assembly and factorise+solve time per Newton iteration
//    against the number of unknowns, axisymmetric incompressible
//    visco-hyperelastic block (nucleus parameters, d0 = 0, mixed u-p)
//  - explicit: element updates per second, 3D hexahedra, Mie-Grueneisen
//  - peak resident memory
// Usage: solidBench [maxImplicitUnknowns (default 1.2e5)]
#include "ExplicitSolver.H"
#include "Loads.H"
#include "StaticSolver.H"

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

using namespace solid;

namespace
{

double peakMemoryMB()
{
    rusage u;
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss/1024.0;
}

void implicitCase(int n)
{
    const double L = 1e-5;
    Model model(Mesh::rectangle(n, n, 0, L, 0, L));
    MaterialParameters p;
    p.name = "nucleus";
    p.C10 = 13.33;
    p.branches = {{862.22, 0.5}};
    model.setMaterial("solid", Material::create(p));
    model.fix("bottom", 0);
    model.fix("bottom", 1);
    model.fix("left", 0);
    model.add(std::make_shared<PressureLoad>("top",
        [](double t) { return 20.0*t; }));
    model.initialise();
    StaticSolver solver(model);
    const StepReport r = solver.step(0.1);
    std::printf("%10d %10d %8d %12.4f %12.4f %12.4f %10.1f\n",
        model.mesh().nElements(), model.nUnknowns(), r.iterations,
        r.assemblySeconds/r.iterations, r.solveSeconds/r.iterations,
        (r.assemblySeconds + r.solveSeconds)/r.iterations, peakMemoryMB());
}

void explicitCase(int n)
{
    const double h = 1e-6;
    Model model(Mesh::box(n, n, n, Vec3(0, 0, 0), Vec3(n*h, n*h, n*h)));
    MaterialParameters p;
    p.name = "cytoplasm";
    p.volumetric = "mieGruneisen";
    p.C10 = 1.67;
    p.branches = {{107.78, 0.01}};
    model.setMaterial("solid", Material::create(p));
    model.fix("zmin", 2);
    model.add(std::make_shared<PressureLoad>("zmax",
        [](double) { return 50e6; }));
    model.initialise();
    ExplicitSolver solver(model);
    const int steps = 20;
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) solver.step();
    const double s = std::chrono::duration<double>(
        std::chrono::steady_clock::now() - t0).count();
    std::printf("%10d %10d %8d %14.3e %12.4f %10.1f\n", model.mesh().nElements(),
        model.nDisplacementDofs(), steps, steps*double(model.mesh().nElements())/s,
        s/steps, peakMemoryMB());
}

} // namespace

int main(int argc, char** argv)
{
    const double maxUnknowns = argc > 1 ? std::atof(argv[1]) : 1.2e5;
    std::printf("# implicit, axisymmetric Q1/P0, d0 = 0 + 1 Maxwell branch, "
                "one load step\n");
    std::printf("%10s %10s %8s %12s %12s %12s %10s\n", "elements",
        "unknowns", "iters", "assembly/it", "solve/it", "total/it",
        "peakMB");
    for (int n : {20, 40, 70, 140, 220})
    {
        if (3.0*n*n > maxUnknowns) break;
        implicitCase(n);
    }
    std::printf("# explicit, 3D hex8, Mie-Grueneisen + bulk viscosity, "
                "20 steps\n");
    std::printf("%10s %10s %8s %14s %12s %10s\n", "elements", "dofs",
        "steps", "elem.upd/s", "s/step", "peakMB");
    for (int n : {10, 20, 40}) explicitCase(n);
    return 0;
}
