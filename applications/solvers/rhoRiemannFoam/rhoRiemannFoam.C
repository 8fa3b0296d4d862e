/*---------------------------------------------------------------------------*\
Application
    rhoRiemannFoam

Group
    grpCompressibleSolvers

Description
    Density-based solver for compressible flow of a fluid with a general
    equation of state (Mie-Grueneisen water, stiffened gas, ideal gas:
    rhoEThermo), for shocks and blast waves in liquids.

    Conservative variables (rho, rho U, rho E); Godunov-type fluxes from an
    approximate Riemann solver (riemannFlux: HLLC, HLL, rusanov) on MUSCL
    face states (limiter per variable in fvSchemes, reconstruct(...));
    strong-stability-preserving Runge-Kutta in time (Shu & Osher, J. Comput.
    Phys. 77, 1988: Euler, SSPRK2, SSPRK3); time step from maxCo with the
    fastest signal speed |U.n| + c. Optional Newtonian viscous stress.

    Every written time holds the conservative state (rho, rhoU, rhoE): a run
    continued from it is exact. Writes are guarded (src/foamTools/
    writeGuard.H): a time directory whose write was interrupted is moved
    aside at the next start from latestTime. Every time step checks that each cell state
    lies inside the domain of the
    equation of state; if not, the run stops naming the cell, its position
    and the time, and the last written time directory is kept.

Usage
    In system/fvSolution:
    \verbatim
        riemann
        {
            riemannSolver   HLLC;       // HLLC | HLL | rusanov
            timeScheme      SSPRK3;     // Euler | SSPRK2 | SSPRK3
            viscous         false;      // add the Newtonian viscous stress
            mu              1e-3;       // dynamic viscosity [Pa s], if viscous
        }
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "rhoEThermo.H"
#include "riemannFlux.H"
#include "rungeKuttaScheme.H"
#include "writeGuard.H"
#include "inputChecks.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Density-based compressible flow solver for a general equation of"
        " state (Mie-Grueneisen water): HLLC/MUSCL/SSP Runge-Kutta."
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    foamTools::writeGuard::discardIncompleteTimes(args);
    #include "createTime.H"
    #include "createMesh.H"
    foamTools::checkCellVolumes(mesh);
    #include "createFields.H"
    #include "createTimeControls.H"
    foamTools::checkTimeControls(runTime, adjustTimeStep, maxCo, maxDeltaT);

    Info<< "\nStarting time loop\n" << endl;

    while (foamTools::writeGuard::run(runTime))
    {
        #include "readTimeControls.H"
        foamTools::checkTimeControls(runTime, adjustTimeStep, maxCo, maxDeltaT);

        flux->fluxes(thermo, U, phi, phiU, phiE, amaxSf);

        #include "courantNo.H"
        #include "setDeltaT.H"

        ++runTime;

        Info<< "Time = " << runTime.timeName() << " s" << nl << endl;

        const scalarField rhoOld(rho.primitiveField());
        const vectorField rhoUOld(rhoU.primitiveField());
        const scalarField rhoEOld(rhoE.primitiveField());

        for (label stage = 0; stage < rk.nStages(); ++stage)
        {
            if (stage > 0)
            {
                // An invalid stage state stops here with the cell named
                // (not as a floating-point exception in the flux)
                thermo.checkStates();
                flux->fluxes(thermo, U, phi, phiU, phiE, amaxSf);
            }

            #include "conservativeStage.H"
        }

        thermo.checkStates();

        foamTools::writeGuard::write(runTime);

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}
