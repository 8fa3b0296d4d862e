// Writes two small solid result files with the solid library for the
// solidToFoam test: an axisymmetric r-z block (cylinder of radius R, height
// H, on the axis) and a 3D box, each compressed by a top pressure in two
// quasi-static steps. Usage: makeSolidResults <directory>
#include "Loads.H"
#include "Material.H"
#include "ResultWriter.H"
#include "StaticSolver.H"
#include "StringEntries.H"

#include <iostream>
#include <map>
#include <memory>
#include <string>

using namespace solid;

namespace
{

std::shared_ptr<const Material> material()
{
    const std::map<std::string, std::string> entries
    {
        {"C10", "100"},      // [Pa]
        {"d0", "1e-3"},     // [1/Pa]: bulk modulus 2000 Pa
        {"mu1", "50"},      // [Pa]
        {"tau1", "1"}       // [s]
    };
    return Material::create
    (
        MaterialParameters::fromEntries
        (
            "solid", StringEntries("material 'solid'", entries)
        )
    );
}

void run(Model& model, const std::string& base, const std::string& top)
{
    model.setMaterial("solid", material());
    model.add(std::make_shared<PressureLoad>(top,
        [](double t) { return 20.0*t; }));        // [Pa]
    model.initialise();
    StaticSolver solver(model);
    ResultWriter out(base, model);
    out.write(model);
    for (int i = 0; i < 2; ++i)
    {
        solver.step(0.5);                         // [s]
        out.write(model);
    }
    std::cout << "wrote " << out.h5File() << '\n';
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    if (argc != 2)
    {
        std::cerr << "usage: makeSolidResults <directory>\n";
        return 1;
    }
    const std::string dir(argv[1]);

    Model axi(Mesh::rectangle(4, 3, 0, 2e-6, 0, 3e-6));  // R 2 um, H 3 um
    axi.fix("bottom", 1);
    axi.fix("left", 0);
    run(axi, dir + "/axisymmetric", "top");

    Model box(Mesh::box(3, 2, 4, {0, 0, 0}, {3e-6, 2e-6, 4e-6}));
    box.fix("zmin", 0);
    box.fix("zmin", 1);
    box.fix("zmin", 2);
    run(box, dir + "/box", "zmax");
    return 0;
}
