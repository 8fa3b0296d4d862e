/*---------------------------------------------------------------------------*\
Application
    rhoRiemannFoam

Group
    grpCompressibleSolvers

Description
    Density-based solver for compressible flow of a fluid with a general
    equation of state (Mie-Grueneisen water, stiffened gas, ideal gas:
    rhoEThermo), for shocks and blast waves in liquids.

    The fluid is a conservativeFluid (src/fluid): conservative variables
    (rho, rho U, rho E), Godunov-type fluxes from an approximate Riemann
    solver (riemannFlux: HLLC, HLL, rusanov) on MUSCL face states,
    strong-stability-preserving Runge-Kutta in time (Euler, SSPRK2,
    SSPRK3), optional Newtonian viscous stress. Time step from maxCo with
    the fastest signal speed |U.n| + c.

    Writes are guarded (src/foamTools/writeGuard.H): a time directory whose
    write was interrupted is moved aside at the next start from latestTime.
    Every time step checks that each cell state lies inside the domain of
    the equation of state; if not, the run stops naming the cell, its
    position and the time, and the last written time directory is kept.

Usage
    system/fvSolution riemann{} (see src/fluid/conservativeFluid), 0/p,
    0/T, 0/U, constant/thermophysicalProperties (docs/userGuide/).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "conservativeFluid.H"
#include "writeGuard.H"
#include "heapPolicy.H"
#include "fvInputChecks.H"
#include "caseLock.H"
#include "postProcessGuard.H"
#include "resultGuard.H"
#include "restartLogs.H"
#include "inputRecord.H"

int main(int argc, char *argv[])
{
    foamTools::keepFreedMemory();

    argList::addNote
    (
        "Density-based compressible flow solver for a general equation of"
        " state (Mie-Grueneisen water): HLLC/MUSCL/SSP Runge-Kutta."
    );

    // -dry-run's simplified mesh: a written time's fields cannot be read
    // on it, and its end time is unbounded (adv40 z03)
    const char* const dryRunReason =
        "the fields of a time a run wrote (their boundary values per face of"
        " the case's mesh) cannot be read on it, nor the run's step count"
        " checked (the mode sets an unbounded end time): it would fail with"
        " a reason that is not the case's";
    // -postProcess and -dry-run refused, options, case path and
    // numbers checked, the case locked, then createTime.H
    #include "createTimeChecked.H"
    // the start time's fields (but p, U, T: the record names an edited
    // boundary condition) as the run wrote them, before they are read: a
    // damaged rho ended in a floating-point exception (adv47a f07)
    foamTools::writeGuard::verifyStateFields(args, runTime);
    #include "createMesh.H"
    foamTools::checkCellVolumes(mesh);
    // the mesh the restart time's fields were computed on, before they are
    // read (a mesh of another size: OpenFOAM's size error, adv53 l01 (b))
    foamTools::inputRecord::checkWholeMesh(runTime, mesh);

    #include "createFields.H"

    #include "createTimeControls.H"
    foamTools::checkTimeControls(runTime, adjustTimeStep, maxCo, maxDeltaT);
    // Probes and other function objects: types, keywords, fields
    foamTools::checkFunctionObjects(runTime, mesh);
    // The number of steps, estimated: deltaT, or with adjustTimeStep the
    // Courant limit of the start state within maxDeltaT
    if (adjustTimeStep)
    {
        fluid.fluxes();
        const scalar Co = fluid.courantNumber(runTime.deltaTValue());
        const scalar dtCo = maxCo*runTime.deltaTValue()/max(Co, SMALL);
        OStringStream how;
        how << "the smaller of maxDeltaT = "
            << foamTools::numberText(maxDeltaT).c_str() << " s and the "
            << "Courant limit maxCo = " << foamTools::numberText(maxCo).c_str()
            << " of the start state, " << foamTools::numberText(dtCo).c_str()
            << " s";
        foamTools::checkStepCount(runTime, min(maxDeltaT, dtCo), how.str());
    }
    else
    {
        foamTools::checkStepCount(runTime, runTime.deltaTValue(), "deltaT");
    }

    // Inputs read and checked; a new start stops here if it would replace
    // the results of an earlier run, a restart if its inputs are not those
    // its results were computed with
    foamTools::resultGuard::check(args, runTime);
    const foamTools::inputRecord inputs(runTime, mesh);
    inputs.checkRestart();
    // the start time's files and the mesh as the run that wrote them
    // left them (their digests at the commit; adv33 sh05, b13): after the
    // record, which names an input that changed (a boundary condition, a
    // mesh point) as such
    foamTools::writeGuard::verify(args, runTime);
    // the probes' logs a restart continues complete up to its time
    foamTools::checkRestartLogs(runTime, wordList());

    Info<< "\nStarting time loop\n" << endl;

    while (foamTools::writeGuard::run(runTime))
    {
        #include "readTimeControls.H"
        foamTools::checkTimeControls(runTime, adjustTimeStep, maxCo, maxDeltaT);

        fluid.fluxes();

        const scalar CoNum = fluid.courantNumber(runTime.deltaTValue());
        // a fixed deltaT above the stability limit stops before its step
        foamTools::checkCourantNumber(runTime, adjustTimeStep, CoNum);
        #include "setDeltaT.H"

        ++runTime;

        Info<< "Time = " << runTime.timeName() << " s" << nl << endl;

        fluid.storeOldState();
        fluid.step(runTime.deltaTValue());
        fluid.thermo().checkStates();

        foamTools::writeGuard::write(runTime, [&]{ inputs.write(); });

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
