/*---------------------------------------------------------------------------*\
Application
    cellBlastFoam

Group
    grpCompressibleSolvers

Description
    Partitioned fluid-structure interaction of the compressible water
    (src/fluid conservativeFluid: HLLC/MUSCL/SSP Runge-Kutta, rhoEThermo,
    ALE on the moving mesh) with the explicit solid (src/solid, central
    difference, Mie-Grueneisen or hyperelastic regions), for a cell under a
    blast wave. The coupled step, its time-step control, restart state and
    logs are src/fsi fluidSolidInteraction's; this loop runs it.

    Serial or parallel (decomposePar, -parallel: the fluid decomposed, the
    solid whole on every rank). Restart with startFrom latestTime: exact
    (tests/blast/restart.sh); a time whose write was interrupted is moved
    aside.

Usage
    constant/fsiProperties, constant/solidProperties,
    constant/dynamicMeshDict, 0/pointDisplacement, and the fluid's inputs
    (docs/userGuide/fsi.md).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "dynamicFvMesh.H"
#include "conservativeFluid.H"
#include "fluidSolidInteraction.H"
#include "writeGuard.H"
#include "heapPolicy.H"
#include "caseLock.H"
#include "postProcessGuard.H"
#include "resultGuard.H"
#include "restartLogs.H"
#include "inputRecord.H"
#include "fvInputChecks.H"

int main(int argc, char *argv[])
{
    foamTools::keepFreedMemory();

    argList::addNote
    (
        "Fluid-structure interaction of the compressible water solver with"
        " the explicit solid (cell under blast)."
    );

    // -dry-run's simplified mesh: it cannot be coupled (adv40 z02)
    const char* const dryRunReason =
        "the coupling of its interface patch to the solid's mesh cannot be"
        " checked on it (the interface map would fail with a false reason)";
    // -postProcess and -dry-run refused, options, case path and
    // numbers checked, the case locked, then createTime.H
    #include "createTimeChecked.H"

    // The number of steps, at least (before the mesh and the start
    // time's state are read: a start after endTime is named as such, was
    // OpenFOAM's "Istream not OK" for its uniform/time, adv28 v05): the steps are at most maxDeltaT with
    // adjustTimeStep, else deltaT (a lower bound: the Courant and the
    // solid's limits are known only once the coupling exists, which
    // writes solid.h5; not estimated)
    {
        const dictionary& cd = runTime.controlDict();
        const bool adjust = cd.getOrDefault<bool>("adjustTimeStep", false);
        const scalar maxDeltaT = cd.getOrDefault<scalar>("maxDeltaT", GREAT);
        // deltaT, maxDeltaT > 0, maxCo in (0, 1] (adv32 pr21)
        foamTools::checkTimeControls
        (
            runTime, adjust, cd.getOrDefault<scalar>("maxCo", 1.0), maxDeltaT
        );
        if (adjust)
        {
            foamTools::checkStepCount(runTime, maxDeltaT, "maxDeltaT");
        }
        else
        {
            foamTools::checkStepCount
            (
                runTime, runTime.deltaTValue(), "deltaT"
            );
        }
    }

    // A restart's dynamicMeshDict before the mesh is built: a motion
    // solver switched on there reads its fields while the mesh is built,
    // and OpenFOAM's "cannot find file 0/pointDisplacement" came before
    // the input record named the change (adv37 w17); every other input
    // is compared below, after its own checks
    if (!foamTools::resultGuard::newStart(runTime))
    {
        foamTools::inputRecord(runTime).checkRestart
        (
            {"constant/dynamicMeshDict"}
        );
    }

    // the start time's fields (but p, U, T: the record names an edited
    // boundary condition) as the run wrote them, before they are read: a
    // damaged rho ended in a floating-point exception (adv47a f07)
    foamTools::writeGuard::verifyStateFields(args, runTime);
    autoPtr<dynamicFvMesh> meshPtr
    (
        fluidSolidInteraction::newMesh(args, runTime)
    );
    dynamicFvMesh& mesh = meshPtr();
    // the mesh the restart time's fields were computed on, before they are
    // read (a mesh of another size: OpenFOAM's size error, adv53 l01 (b))
    foamTools::inputRecord::checkWholeMesh(runTime, mesh);

    #include "createFields.H"
    // The viscous stress's step limit (a property of the start state and
    // the mesh, unlike the waves' Courant limit): mu 1e6 Pa s gave steps
    // of 7.8e-18 s, 1e10 steps to endTime, run without end (adv32 f30)
    {
        const dictionary& cd = runTime.controlDict();
        const scalar maxDeltaT = cd.getOrDefault<scalar>("maxDeltaT", GREAT);
        const scalar dtViscous =
            fluid.viscousDeltaT(cd.getOrDefault<scalar>("maxCo", 1.0));
        if (cd.getOrDefault<bool>("adjustTimeStep", false)
         && dtViscous < maxDeltaT)
        {
            OStringStream how;
            how << "the viscous limit of maxCo with entry 'mu' = "
                << foamTools::numberText(fluid.mu().value()).c_str()
                << " Pa s of system/fvSolution riemann, below maxDeltaT = "
                << foamTools::numberText(maxDeltaT).c_str() << " s";
            foamTools::checkStepCount(runTime, dtViscous, how.str());
        }
    }
    // Probes and other function objects: types, keywords, fields
    foamTools::checkFunctionObjects(runTime, mesh);
    // A new start stops here, before the coupling writes, if it would
    // replace the results of an earlier run; a restart if its inputs are
    // not those its results were computed with
    // A start from a time of the earlier run continues its solid.h5 (the
    // step uniform/solidState names): -overwrite, which would move it
    // aside, is refused (adv36 v70)
    foamTools::resultGuard::check
    (
        args, runTime,
        {
            runTime.globalPath()/"solid"/"solid.h5",
            runTime.globalPath()/"solid"/"solid.xmf"
        },
        isFile
        (
            runTime.timePath()/"uniform"
           /foamTools::uniformState::solidState()
        )
      ? fileNameList(1, runTime.globalPath()/"solid"/"solid.h5")
      : fileNameList()
    );
    const foamTools::inputRecord inputs(runTime, mesh);
    inputs.checkRestart();
    // the start time's files and the mesh as the run that wrote them
    // left them (their digests at the commit; adv33 sh05, b13): after the
    // record, which names an input that changed (a boundary condition, a
    // mesh point) as such
    foamTools::writeGuard::verify(args, runTime);
    // the logs a restart continues complete up to its time (adv35 k13,
    // k14: a cut solidProbes.dat or coupling.dat continued without a word)
    foamTools::checkRestartLogs
    (
        runTime, {"fsi", "solidProbes", "solidInterfaces"}
    );

    fluidSolidInteraction fsi(mesh, fluid);

    Info<< "\nStarting time loop\n" << endl;

    // First time step from the initial state; a restart continues with the
    // time step saved with its time
    if (!(runTime.value() > 0))
    {
        fluid.fluxes();
        fsi.setDeltaT();
    }

    while (foamTools::writeGuard::run(runTime))
    {
        ++runTime;
        const scalar stepDeltaT = runTime.deltaTValue();

        Info<< "Time = " << runTime.timeName() << " s" << nl << endl;

        fsi.step();

        fluid.thermo().checkStates();

        fsi.setDeltaT();

        // Fluid fields, then the solid and the coupling state and the
        // record of the inputs, inside the write markers: a time whose write was interrupted is moved aside
        // at the restart
        foamTools::writeGuard::write
        (
            runTime,
            [&]{ fsi.write(stepDeltaT); inputs.write(); }
        );

        runTime.printExecutionTime(Info);
    }

    fsi.report();

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
