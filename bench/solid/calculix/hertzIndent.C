// Our side of the CalculiX benchmark (not a test): a rigid sphere pressed
// into an axisymmetric nearly incompressible neo-Hookean block read from a
// gmsh mesh (geometry in um, groups solid, bottom, left, contact; written
// by hertzMesh.py together with the CalculiX input of the same nodes).
// Prints one line "key value" per result, SI units.
//
// Usage: hertzIndent mesh.msh R[m] depth[m] mu[Pa] K[Pa] nSteps tolerance[m]
#include "GmshReader.H"
#include "RigidSphereContact.H"
#include "StaticSolver.H"

#include <chrono>
#include <cstdio>
#include <cstdlib>

using namespace solid;

int main(int argc, char** argv)
{
    if (argc != 8)
    {
        std::fprintf(stderr, "usage: %s mesh.msh R depth mu K nSteps "
            "tolerance\n", argv[0]);
        return 2;
    }
    const double R = std::atof(argv[2]), depth = std::atof(argv[3]);
    const double mu = std::atof(argv[4]), K = std::atof(argv[5]);
    const int nSteps = std::atoi(argv[6]);
    const double tolerance = std::atof(argv[7]);
    const auto t0 = std::chrono::steady_clock::now();

    Model model(readGmsh(argv[1], 1e-6));
    double zTop = 0;
    for (const Vec3& X : model.mesh().X) zTop = std::max(zTop, X(1));

    // Psi = C10 (I1bar - 3) + (J - 1)^2/d0: mu = 2 C10, K = 2/d0, the
    // CalculiX *HYPERELASTIC, NEO HOOKE form with the same C10, D1 = d0
    MaterialParameters p;
    p.name = "solid";
    p.C10 = mu/2;
    p.d0 = 2/K;
    model.setMaterial("solid", Material::create(p));
    model.fix("bottom", 0);
    model.fix("bottom", 1);
    model.fix("left", 0);

    RigidSphereSettings s;
    s.radius = R;
    s.centre0 = Vec3(0, zTop + R, 0);
    s.direction = Vec3(0, -1, 0);
    s.depth = [depth](double t) { return depth*t; };
    s.tolerance = tolerance;
    auto contact = std::make_shared<RigidSphereContact>("contact", s);
    model.add(contact);
    model.initialise();

    StaticSolver solver(model);
    int iterations = 0, augmentations = 0, cuts = 0;
    double assembly = 0, solve = 0;
    for (int k = 0; k < nSteps; ++k)
    {
        const StepReport r = solver.step(1.0/nSteps);
        iterations += r.iterations;
        augmentations += r.augmentations;
        cuts += r.cuts;
        assembly += r.assemblySeconds;
        solve += r.solveSeconds;
    }
    const ContactReport c = contact->report(model, model.u, model.time);
    const double seconds = std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();

    std::printf("elements %d\n", model.mesh().nElements());
    std::printf("unknowns %d\n", model.nFree());
    std::printf("force %.10e\n", c.force);
    std::printf("contactRadius %.6e\n", c.contactRadius);
    std::printf("maxPenetration %.6e\n", c.maxPenetration);
    std::printf("iterations %d\n", iterations);
    std::printf("augmentations %d\n", augmentations);
    std::printf("cuts %d\n", cuts);
    std::printf("assemblySeconds %.4f\n", assembly);
    std::printf("solveSeconds %.4f\n", solve);
    std::printf("seconds %.4f\n", seconds);
    return 0;
}
