// planeShockRest: does the explicit solid return to rest after a plane
// shock has passed? (issue 17 items 5 and 6; not a test)
//
// The scene is bench/solid/planeShockColumn.H. For the aligned, smooth
// and random meshes, element sizes h, the two volumetric integrations
// (element: the Q1/P0 mean dilatation, with hourglass viscosities kappa;
// gaussPoints: the volumetric law at the 2x2 Gauss points, kappa 0) and
// the pulse's ramp (0.1 ns: a shock thinner than an element; 1 ns: a
// resolved front), the largest and the rms |ln stretch_z| and the largest
// von Mises left behind the pulse.
//
// Usage: planeShockRest [h1 h2 ...]   (default 0.5e-6 0.25e-6 0.125e-6)
//        planeShockRest MESH H KAPPA RAMP element|gaussPoints [BETA
//                       [filtered]]                           (one case;
//                   BETA: the deviatoric numerical viscosity, default 0;
//                   filtered: its scale-selective form)
//   cmake --build build --target planeShockRest && build/bin/planeShockRest
#include "planeShockColumn.H"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{

void print(const planeShock::Options& o)
{
    const planeShock::Result r = planeShock::run(o);
    std::printf("%-8s %7.3g %-11s %6.3g %6.3g%s %8.2g %11.3e %11.3e %8.3g "
        "%8.3g %8ld %9.5f %8.4f %8.4f\n", o.mesh.c_str(), o.h*1e6,
        o.gaussPoints ? "gaussPoints" : "element", o.kappa, o.beta,
        o.filter ? "f" : " ", o.ramp*1e9,
        r.maxStrain, r.rmsStrain, r.rAtMax*1e6, r.maxVonMises, r.steps,
        r.plateauPressure, r.plateauVonMises, r.plateauVonMisesRms);
    std::fflush(stdout);
}

} // namespace


int main(int argc, char** argv)
{
    std::printf("# plane shock (50 MPa, 5 ns) through an r-z column of cell "
        "material; at 24 ns, elements in z = [20, 30] um (passed by the "
        "pulse, before its echo): largest and rms |ln stretch_z| [-], the "
        "radius of the largest [um], largest von Mises [Pa]; the exact "
        "answer: 0 and 0 (peak while passing: strain 0.022, von Mises "
        "5.2 Pa); while passing (15 ns, z = [18.5, 23.5] um, the "
        "plateau): mean pressure / P, mean von Mises [Pa], rms of the "
        "elements' von Mises about it / mean (exact: 1, 5.2 Pa, 0); beta "
        "f: the filtered form\n");
    std::printf("%-8s %7s %-11s %6s %7s %8s %11s %11s %8s %8s %8s %9s "
        "%8s %8s\n", "mesh", "h[um]", "volumetric", "kappa", "beta",
        "ramp[ns]", "maxStrain", "rmsStrain", "rMax[um]", "vM[Pa]",
        "steps", "p/P", "vM[Pa]", "vMrms");
    planeShock::Options o;
    if (argc >= 6 && argc <= 8)
    {
        o.beta = argc >= 7 ? std::atof(argv[6]) : 0;
        o.filter = argc == 8 && std::string(argv[7]) == "filtered";
        if (argc == 8 && !o.filter)
        {
            std::fprintf(stderr, "planeShockRest: 7th argument '%s': "
                "valid is 'filtered'\n", argv[7]);
            return 1;
        }
        o.mesh = argv[1];
        o.h = std::atof(argv[2]);
        o.kappa = std::atof(argv[3]);
        o.ramp = std::atof(argv[4]);
        o.gaussPoints = std::string(argv[5]) == "gaussPoints";
        print(o);
        return 0;
    }
    std::vector<double> hs;
    for (int i = 1; i < argc; ++i) hs.push_back(std::atof(argv[i]));
    if (hs.empty()) hs = {0.5e-6, 0.25e-6, 0.125e-6};
    for (const char* mesh : {"aligned", "smooth", "random"})
    {
        for (const double ramp : {0.1e-9, 1e-9})
        {
            for (const double h : hs)
            {
                o.mesh = mesh;
                o.h = h;
                o.ramp = ramp;
                o.gaussPoints = false;
                for (const double kappa : {0.0, 0.1, 0.2})
                {
                    o.kappa = kappa;
                    print(o);
                }
                o.gaussPoints = true;
                o.kappa = 0;
                print(o);
            }
        }
    }
}
