/*---------------------------------------------------------------------------*\
Application
    cellIndentationFoam

Description
    Quasi-static nanoindentation of the axisymmetric (or 3D) cell by a
    rigid sphere through a multi-rate loading table (Jerusalem & Dao 2012,
    sec. 2.2.1 and 3; Table 1). Solid only: the solid library (src/solid)
    with incompressible visco-hyperelastic regions (Q1/P0, mixed u-p), a
    frictionless augmented-Lagrangian sphere contact and backward-Euler
    Newton steps sized by the loading rate (a depth increment per step)
    and, in holds, growing geometrically from a small first step (the
    Maxwell branches relax in 0.01 s .. 3000 s).

    Inputs (every entry validated; a bad one is a FatalIOError naming the
    file and the entry):
        constant/cell.msh           gmsh mesh in metres (cellMesh)
        constant/solidProperties    one sub-dictionary per region with the
                                    entries of MaterialParameters, or
                                    parameterSet table|text|textFactor4|
                                    instantaneous
        constant/indenterProperties sphere, contact, stepping, protocol
        system/controlDict          fieldWriteInterval [s] of the field output

    Outputs (postProcessing/indentation/):
        force.dat   time [s], depth [m], force [N], contact radius [m],
                    max penetration [m], stage (header line)
        peaks.dat   the cycle maxima and F at the end of B and E
        solid.h5/.xmf   fields (pressure, von Mises, ...) at the peaks, at
                    the stage ends B and E and every fieldWriteInterval;
                    ParaView opens solid.xmf

Usage
    cellIndentationFoam [-case dir]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "OSspecific.H"

#include "Checkpoint.H"
#include "GmshReader.H"
#include "IndentationProtocol.H"
#include "ResultWriter.H"
#include "RigidSphereContact.H"
#include "SolidError.H"
#include "StaticSolver.H"


#include <chrono>
#include <ctime>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <unistd.h>

using namespace Foam;

#include "readInputs.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Quasi-static indentation of the cell by a rigid sphere through a "
        "multi-rate loading table (solid only)"
    );
    argList::noParallel();
    #include "setRootCase.H"
    #include "createTime.H"

    #include "createModel.H"
    #include "createIndenter.H"

    // Wall and CPU time: on a shared machine the CPU time of this process
    // is the one-core cost
    const auto wall0 = std::chrono::steady_clock::now();
    const std::clock_t cpu0 = std::clock();
    #include "runProtocol.H"
    const double wall = std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - wall0
    ).count();
    const double cpu = double(std::clock() - cpu0)/CLOCKS_PER_SEC;

    Info<< nl << "Protocol done: " << nSteps << " steps, " << nIterations
        << " Newton iterations, " << nAugmentations << " augmentations, "
        << nCuts << " step cuts, " << contact->penaltyRaises()
        << " penalty raises, wall time " << wall << " s, CPU time "
        << cpu << " s (assembly "
        << assemblySeconds << " s, factorise + solve " << solveSeconds
        << " s)" << nl
        << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
