// Our side of the layer indentation benchmark (not a test): a rigid sphere
// pressed into an axisymmetric bonded neo-Hookean layer read from a gmsh
// mesh (geometry in um, groups solid, bottom, left, contact; written by
// bench/solid/layer/run.py with layerMesh.py and hertzMesh.py, the
// CalculiX input of the same nodes beside it). The depth grows linearly
// with the pseudo-time t in [0, 1] to the last depth, in increments of at
// most the given step; the force is reported at each listed depth.
// Prints "depth <m> force <N> contactRadius <m> maxPenetration <m>" per
// depth, then "key value" lines; SI units.
//
// Usage: layerIndent mesh.msh R[m] mu[Pa] K[Pa] (0: incompressible)
//        step[m] tolerance[m] depth1[m] [depth2 ...] (ascending)
#include "GmshReader.H"
#include "RigidSphereContact.H"
#include "StaticSolver.H"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace solid;

int main(int argc, char** argv)
{
    if (argc < 8)
    {
        std::fprintf(stderr, "usage: %s mesh.msh R mu K step tolerance "
            "depth1 [depth2 ...]\n", argv[0]);
        return 2;
    }
    const double R = std::atof(argv[2]), mu = std::atof(argv[3]);
    const double K = std::atof(argv[4]), step = std::atof(argv[5]);
    const double tolerance = std::atof(argv[6]);
    std::vector<double> depths;
    for (int k = 7; k < argc; ++k) depths.push_back(std::atof(argv[k]));
    bool ok = R > 0 && mu > 0 && K >= 0 && step > 0 && tolerance > 0;
    for (std::size_t k = 0; k < depths.size(); ++k)
    {
        ok = ok && depths[k] > (k ? depths[k - 1] : 0.0);
    }
    if (!ok)
    {
        std::fprintf(stderr, "%s: need R, mu, step, tolerance > 0, K >= 0 "
            "and depths > 0 ascending (SI units)\n", argv[0]);
        return 2;
    }
    const double dMax = depths.back();
    const auto t0 = std::chrono::steady_clock::now();

    Model model(readGmsh(argv[1], 1e-6));
    double zTop = 0;
    for (const Vec3& X : model.mesh().X) zTop = std::max(zTop, X(1));

    // Psi = C10 (I1bar - 3) + (J - 1)^2/d0: mu = 2 C10, K = 2/d0 (the
    // CalculiX NEO HOOKE form with the same C10, D1 = d0); K = 0 selects
    // d0 = 0, the exactly incompressible law
    MaterialParameters p;
    p.name = "solid";
    p.C10 = mu/2;
    p.d0 = K > 0 ? 2/K : 0;
    model.setMaterial("solid", Material::create(p));
    model.fix("bottom", 0);
    model.fix("bottom", 1);
    model.fix("left", 0);

    RigidSphereSettings s;
    s.radius = R;
    s.centre0 = Vec3(0, zTop + R, 0);
    s.direction = Vec3(0, -1, 0);
    s.depth = [dMax](double t) { return dMax*t; };
    s.tolerance = tolerance;
    auto contact = std::make_shared<RigidSphereContact>("contact", s);
    model.add(contact);
    model.initialise();

    StaticSolver solver(model);
    int iterations = 0, augmentations = 0, cuts = 0;
    double done = 0;
    for (const double d : depths)
    {
        const int n = std::max(1, int(std::ceil((d - done)/step - 1e-9)));
        for (int k = 1; k <= n; ++k)
        {
            // Pseudo-time of the sub-step end, hit exactly at each depth
            const double tEnd = (done + (d - done)*k/n)/dMax;
            const StepReport r = solver.step(tEnd - model.time);
            iterations += r.iterations;
            augmentations += r.augmentations;
            cuts += r.cuts;
        }
        done = d;
        const ContactReport c = contact->report(model, model.u, model.time);
        std::printf("depth %.10e force %.10e contactRadius %.6e "
            "maxPenetration %.6e\n", dMax*model.time, c.force,
            c.contactRadius, c.maxPenetration);
    }
    const double seconds = std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();

    std::printf("elements %d\n", model.mesh().nElements());
    std::printf("unknowns %d\n", model.nFree());
    std::printf("iterations %d\n", iterations);
    std::printf("augmentations %d\n", augmentations);
    std::printf("cuts %d\n", cuts);
    std::printf("seconds %.4f\n", seconds);
    return 0;
}
