/*---------------------------------------------------------------------------*\
Application
    cellMesh

Description
    Meshes the neuron cell of Jerusalem & Dao (semi-spheroid on a substrate
    with a nucleus and a membrane+cortex layer) with gmsh from
    system/cellMeshDict and writes constant/cell.msh (gmsh 4.1, metres):
    an axisymmetric r-z section of quadrilaterals or a 3D (full or quarter)
    cell of hexahedra, with the physical groups read by the solid library
    (readGmsh). With the subdictionary fluid it also writes the water box
    around the cell, constant/fluid.msh (gmsh 2.2 for gmshToFoam; a wedge
    in the axisymmetric mode). Prints a quality report. Any invalid entry
    is a FatalIOError naming the entry, and nothing is written.

    Dictionary entries, geometry and groups: docs/userGuide/cellMesh.md,
    cellGeometry.H and cellMesher.H.

Usage
    cellMesh [-case dir] [-dict file]

\*---------------------------------------------------------------------------*/

#include <cerrno>
#include <new>
#include <stdexcept>
#include <cstring>
#include <unistd.h>
#include "argList.H"
#include "inputChecks.H"
#include "cellGeometry.H"
#include "cellMesher.H"
#include "fluidBox.H"
#include "mshFile.H"
#include "Pair.H"
#include <memory>
#include "sigFpe.H"
#include <gmsh.h>
#include "caseLock.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Mesh the cell (nucleus, cytoplasm, membrane) from "
        "system/cellMeshDict into constant/cell.msh"
    );
    argList::noParallel();
    argList::addOption("dict", "file", "Alternative cellMeshDict");

    // setRootCase.H with checkCasePath before OpenFOAM checks the case
    #include "setRootCaseChecked.H"
    // one writer per case: a solver running in it (or another utility)
    // is named and nothing is written (adv33 lk10: setRiemannProblem
    // -overwrite removed a running solver's time directories)
    const foamTools::caseLock lock(args);
    foamTools::checkOptions(args);     // no nan, inf or 1e999 in options

    const fileName dictFile
    (
        args.getOrDefault<fileName>("dict", args.path()/"system/cellMeshDict")
    );
    if (isDir(dictFile))
    {
        FatalErrorInFunction
            << "option -dict " << dictFile << " is a directory: give the"
            << " cellMeshDict file (default system/cellMeshDict)"
            << exit(FatalError);
    }
    // The meshes go to constant/: a file of that name (adv28 m17: "gmsh
    // failed (nothing written)") is said as such, before anything is meshed
    const fileName constantDir(args.path()/"constant");
    const std::string kind(foamTools::notARegularFile(constantDir));
    if (exists(constantDir) && kind != "a directory")
    {
        FatalErrorInFunction
            << constantDir << " is "
            << (kind.empty() ? "a file" : kind.c_str()) << ", not a"
            << " directory: cellMesh writes constant/cell.msh (and"
            << " constant/fluid.msh) into the directory constant of the"
            << " case. Move it aside. Nothing was meshed or written"
            << exit(FatalError);
    }
    // ... and one it cannot write into (a read-only file system, adv37
    // w57: meshed, then gmsh's "Unable to open file" without the reason)
    if (isDir(constantDir) && ::access(constantDir.c_str(), W_OK) != 0)
    {
        const std::string reason(std::strerror(errno));
        FatalErrorInFunction
            << constantDir << " cannot be written into (" << reason.c_str()
            << "): cellMesh writes constant/cell.msh (and constant/"
            << "fluid.msh) there. Nothing was meshed or written"
            << exit(FatalError);
    }
    const cellGeometry geom(dictFile);
    // Validated before anything is meshed
    std::unique_ptr<fluidBox> fluid;
    if (!geom.fluidDict().empty())
    {
        fluid.reset(new fluidBox(geom));
    }

    Info<< "Cell: diameter " << 2*geom.a() << " m, height " << geom.H()
        << " m, mode " << cellGeometry::meshModeNames[geom.mode()] << nl
        << endl;

    // gmsh's meshers rely on IEEE non-stop arithmetic (inf/NaN in
    // discarded candidates): OpenFOAM's trapping would abort them
    sigFpe::unset();
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 1);
    gmsh::option::setNumber("General.Verbosity", 2);
    // A request the system refuses is a std::bad_alloc, caught below and
    // named (OpenFOAM's new handler aborted: adv50a k05 (c), a structured
    // mesh's points under a memory limit, SIGABRT)
    std::set_new_handler(nullptr);
    try
    {
        cellMesher mesher(geom);
        mesher.generate();
        // Both meshes are made before either is written
        if (fluid)
        {
            fluid->generate();
            gmsh::model::setCurrent("cell");
        }
        // Both written and checked before either replaces its file
        const fileName cellFile(args.path()/"constant/cell.msh");
        const fileName fluidFile(args.path()/"constant/fluid.msh");
        List<Pair<fileName>> files
        (
            1, Pair<fileName>(mesher.writeTemporary(cellFile), cellFile)
        );
        if (fluid)
        {
            gmsh::model::setCurrent("fluid");
            files.append
            (
                Pair<fileName>(fluid->writeTemporary(fluidFile), fluidFile)
            );
        }
        mshFile::commit(files);
        Info<< "Written " << cellFile << " (gmsh 4.1, coordinates in m)"
            << endl;
        if (fluid)
        {
            Info<< "Written " << fluidFile << " (gmsh 2.2 for gmshToFoam,"
                << " coordinates in m)" << endl;
        }
    }
    catch (const std::bad_alloc& e)
    {
        FatalErrorInFunction
            << "the mesh needs more memory than the system gives this "
            << "process (" << e.what() << ": nucleusSize "
            << geom.nucleusSize() << " m, cytoplasmSize "
            << geom.cytoplasmSize() << " m, membraneSize "
            << geom.membraneSize() << " m, maxElements "
            << geom.maxElements() << "; " << dictFile << "). Nothing was "
            << "written: larger sizes, a smaller maxElements, or more "
            << "memory" << exit(FatalError);
    }
    catch (const std::length_error& e)
    {
        FatalErrorInFunction
            << "the mesh asks for a list longer than a list can hold ("
            << e.what() << ": nucleusSize " << geom.nucleusSize()
            << " m, cytoplasmSize " << geom.cytoplasmSize()
            << " m, membraneSize " << geom.membraneSize() << " m; "
            << dictFile << "). Nothing was written: larger sizes"
            << exit(FatalError);
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction
            << "gmsh: " << e.what() << " (nothing written)" << exit(FatalError);
    }
    catch (...)
    {
        FatalErrorInFunction
            << "gmsh failed (nothing written)" << exit(FatalError);
    }
    gmsh::finalize();

    Info<< "End" << nl << endl;
    return 0;
}
