/*---------------------------------------------------------------------------*\
Application
    cellBlastFoam

Group
    grpCompressibleSolvers

Description
    Partitioned fluid-structure interaction of the compressible water solver
    (rhoRiemannFoam: HLLC/MUSCL/SSP Runge-Kutta, rhoEThermo) with the
    explicit solid (src/solid, central difference, Mie-Grueneisen or
    hyperelastic regions), for a cell under a blast wave.

    Per time step (lock step, dt = min(fluid Courant step, solid stable
    step)): the coupling scheme (src/fsi, constant/fsiProperties) iterates
    the interface velocity x:
      1. the fluid interface moves to d_n + dt x (consistent map of the solid
         nodes to the patch points), the mesh follows (dynamicMeshDict, e.g.
         displacementLaplacian);
      2. the fluid takes an ALE step that satisfies the geometric
         conservation law, (V q)^k = a (V q)^0 + (1 - a)((V q)^k-1 - dt sum F)
         with the stage volumes from the same recursion and the swept face
         volumes (fluxes in the frame of the moving faces, riemannFlux);
      3. the wall force at t_n+1 (momentum flux of the interface faces) is
         mapped conservatively onto the solid nodes, the solid steps;
      4. residual of x~ = (v_n + v_n+1)/2 against x; stop or relax.
    The coupling residual and iterations of every step are written to
    postProcessing/fsi/<time>/coupling.dat; non-converged steps are counted
    and reported (or stop the run).

    Parallel (decomposePar, -parallel): the fluid is decomposed, the solid
    is whole on every rank. The interface map is built on the FSI patch
    of all ranks (src/fsi/globalInterfacePatch); per coupling pass the
    ranks exchange their interface face forces and all take the same
    solid step and coupling update. The master writes solid/solid.h5 and
    the logs at the case root.

    Restart (startFrom latestTime): every write time holds the fluid
    fields and points, the solid state (uniform/solidState and its step in
    solid/solid.h5) and the coupling state (uniform/fsiState), written
    between the markers of src/foamTools/writeGuard.H; a time whose write
    was interrupted is moved aside and the run continues from the latest
    complete one, with the steps of solid.h5 after it removed.

Usage
    constant/fsiProperties (interface and coupling dictionaries, see
    src/fsi/interfaceMap and couplingScheme), constant/solidProperties
    (src/fsi/solidDomain), constant/dynamicMeshDict, 0/pointDisplacement,
    and everything rhoRiemannFoam reads (docs/userGuide/fsi.md).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "dynamicFvMesh.H"
#include "wedgeFvPatch.H"
#include "wedgePolyPatch.H"
#include "pointFields.H"
#include "pointIOField.H"
#include "OFstream.H"
#include "IFstream.H"
#include "rhoEThermo.H"
#include "riemannFlux.H"
#include "rungeKuttaScheme.H"
#include "cpuTime.H"
#include "clockTime.H"
#include "interfaceMap.H"
#include "interfaceMotion.H"
#include "solidDomain.H"
#include "couplingScheme.H"
#include "Checkpoint.H"
#include "SolidError.H"
#include "writeGuard.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Fluid-structure interaction of the compressible water solver with"
        " the explicit solid (cell under blast)."
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    foamTools::writeGuard::discardIncompleteTimes(args);
    #include "createTime.H"
    #include "createFsiMesh.H"
    #include "createFields.H"
    #include "createFsi.H"
    #include "createTimeControls.H"

    // CPU time split of the coupled steps [s]
    cpuTime cpuTimer;
    scalar cpuMotion = 0, cpuFluid = 0, cpuSolid = 0;
    const scalar cpuStart = runTime.elapsedCpuTime();

    Info<< "\nStarting time loop\n" << endl;

    // First time step from the initial state; a restart continues with the
    // time step saved with its time
    if (!(runTime.value() > 0))
    {
        flux->fluxes(thermo, U, phi, phiU, phiE, amaxSf);
        #include "nextDeltaT.H"
    }

    while (foamTools::writeGuard::run(runTime))
    {
        ++runTime;
        const scalar stepDeltaT = runTime.deltaTValue();

        Info<< "Time = " << runTime.timeName() << " s" << nl << endl;

        #include "couplingStep.H"

        thermo.checkStates();

        #include "nextDeltaT.H"

        // Fluid fields, then the solid (probes; at write times its state),
        // then the coupling state, all inside the write markers: a time
        // whose write was interrupted is moved aside at the restart
        foamTools::writeGuard::write(runTime, [&]
        {
            solid.write(stepDeltaT);
            #include "writeFsiState.H"
        });

        runTime.printExecutionTime(Info);
    }

    coupling->report(Info);
    {
        const scalar total = runTime.elapsedCpuTime() - cpuStart;
        Info<< "CPU time of the time loop " << total << " s: mesh motion "
            << cpuMotion << " s, fluid " << cpuFluid << " s, solid "
            << cpuSolid << " s, other (coupling, restore, output) "
            << total - cpuMotion - cpuFluid - cpuSolid << " s" << endl;
    }
    if (couplingLog.valid())
    {
        couplingLog() << "# ";
        coupling->report(couplingLog());
    }

    Info<< "End\n" << endl;

    return 0;
}
