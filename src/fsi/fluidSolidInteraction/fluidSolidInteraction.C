#include "fluidSolidInteraction.H"
#include "fsiRanges.H"
#include "uniformState.H"
#include "runLogFiles.H"
#include "pointIOField.H"
#include "IFstream.H"
#include "clockTime.H"
#include "wedgeFvPatch.H"
#include "Checkpoint.H"
#include "ResultWriter.H"
#include "SolidError.H"
#include "inputChecks.H"
#include "subDict.H"

#include <cmath>
#include <cstdio>
#include <mpi.h>
#include "keywordCheck.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- The interface{} of constant/fsiProperties, after the keyword check of
//  the file and of interface{} (coupling{}: couplingScheme::New)
const Foam::dictionary& checkedInterfaceDict
(
    const Foam::dictionary& fsiProperties
)
{
    using namespace Foam;

    foamTools::checkKeywords(fsiProperties, {"interface", "coupling"});
    const dictionary& interfaceDict =
        foamTools::subDict(fsiProperties, "interface");
    foamTools::checkKeywords
    (
        interfaceDict,
        {
            "fluidPatch", "solidFaceSet", "mapTolerance", "map", "load",
            "axisOrigin", "axisDirection", "motionDistance", "motionNearest",
            "pressureQuadrature"
        }
    );
    return interfaceDict;
}


//- The index of interface{} fluidPatch in the fluid mesh
Foam::label interfacePatchIndex
(
    const Foam::fvMesh& mesh,
    const Foam::dictionary& interfaceDict
)
{
    using namespace Foam;

    const word name(interfaceDict.get<word>("fluidPatch"));
    const label patchi = mesh.boundaryMesh().findPatchID(name);
    if (patchi < 0)
    {
        FatalIOErrorInFunction(interfaceDict)
            << "fluidPatch " << name << " is not a patch of the fluid"
            << " mesh; patches: " << mesh.boundaryMesh().names()
            << exit(FatalIOError);
    }
    return patchi;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::autoPtr<Foam::dynamicFvMesh> Foam::fluidSolidInteraction::newMesh
(
    const argList& args,
    Time& runTime
)
{
    // The interface map pairs the reference points with the solid's, and
    // OpenFOAM computes the wedge patch transformations once, from the mesh
    // it starts with: build the mesh at time 0 (the points of
    // constant/polyMesh), go back to the start time; the constructor then
    // moves it to that time's points, so that a restart sees the geometry
    // of the run it continues, bit for bit
    const instant startInstant(runTime.value(), runTime.timeName());
    const label startIndex = runTime.timeIndex();
    if (runTime.value() > 0)
    {
        runTime.setTime(instant(0, "0"), 0);
    }

    Info<< "Create mesh (reference points)" << nl << endl;

    autoPtr<dynamicFvMesh> meshPtr(dynamicFvMesh::New(args, runTime));

    if (startInstant.value() > 0)
    {
        runTime.setTime(startInstant, startIndex);

        // The exact start time: OpenFOAM takes it from the directory name
        // (1.2e-08), the run it continues was at the accumulated value that
        // uniform/time keeps in full ("value")
        const fileName timeFile(runTime.timePath()/"uniform"/"time");
        if (!isFile(timeFile))
        {
            // A time directory holding only a region's folders (solidToFoam
            // writes <time>/solid/ for viewing, also at a time the fluid
            // run did not write or whose fluid state was removed): not a
            // damaged time of the run but no time of it at all; said so,
            // with the earlier time the run would continue from (was
            // "Restore the time's uniform/ directory, or start from the
            // initial fields", adv48b g16)
            const fileNameList files
            (
                readDir(runTime.timePath(), fileName::FILE)
            );
            const fileNameList dirs
            (
                readDir(runTime.timePath(), fileName::DIRECTORY)
            );
            if (files.empty() && !dirs.empty() && !dirs.found("uniform"))
            {
                std::string names;
                for (const fileName& d : dirs)
                {
                    names += (names.empty() ? "" : ", ") + d + "/";
                }
                word earlier;
                for (const instant& i : TimePaths::findTimes(runTime.path()))
                {
                    if (i.value() < runTime.value() && i.name() != "constant")
                    {
                        earlier = i.name();
                    }
                }
                FatalErrorInFunction
                    << "The run starts at t = " << runTime.timeName()
                    << " s (startFrom latestTime), but that time directory"
                    << " holds only the folder(s) " << names.c_str()
                    << " (a region's files, e.g. solidToFoam's solid/ for "
                    << "viewing), no fluid state (no fields, no uniform/): "
                    << "it is not a time the run wrote. Move "
                    << runTime.timePath() << " away (keep what you need of"
                    << " it)";
                if (!earlier.empty())
                {
                    FatalError
                        << " to continue from " << earlier << ", the"
                        << " latest time before it";
                }
                FatalError << ". Nothing was run" << exit(FatalError);
            }
            // A time directory without the state OpenFOAM writes with it
            // (was OpenFOAM's "Istream not OK for reading dictionary";
            // issue 19, adv28 qk05: uniform/ removed from a restart time)
            FatalErrorInFunction
                << "The run starts at t = " << runTime.timeName() << " s"
                << " (system/controlDict: startFrom "
                << runTime.controlDict().getOrDefault<word>
                   (
                       "startFrom", "startTime"
                   )
                << "), but that time directory has no "
                << "uniform/time: " << timeFile << " is missing (OpenFOAM"
                << " writes it with every time, with the solid's"
                << " uniform/solidState; a restart needs both). Restore the"
                << " time's uniform/ directory, or start from the initial"
                << " fields (startFrom startTime, startTime 0, -overwrite)"
                << exit(FatalError);
        }
        IFstream is(timeFile);
        const dictionary timeDict(is);
        runTime.setTime(timeDict.get<scalar>("value"), startIndex);
    }

    return meshPtr;
}


void Foam::fluidSolidInteraction::truncateSolidResults(const Time& runTime)
{
    // solid/solid.h5 may hold steps after this time's (h5Step of
    // uniform/solidState), written by the run that stopped: a write
    // interrupted after its solid step, whose time the write guard moved
    // aside, or later times. They are removed (atomically, a copy replaces
    // the file) so that the steps continue from this time's, as in an
    // uninterrupted run. A missing state is reported by solidDomain::couple
    const fileName stateFile
    (
        runTime.timePath()/"uniform"/foamTools::uniformState::solidState()
    );
    const fileName h5(runTime.globalPath()/"solid"/"solid.h5");
    if (!Pstream::master() || !isFile(stateFile) || !isFile(h5))
    {
        return;
    }

    // The file must be this run's and undamaged anywhere (issue 19,
    // classes 1 and 5: a solid.h5 of another run or damaged in an earlier
    // step was continued), checked before anything is removed
    {
        IFstream is(stateFile);
        const dictionary d(is);
        const string runId(d.lookupOrDefault<string>("runId", string()));
        try
        {
            solid::ResultWriter::checkContinued(h5, runId);
        }
        catch (const solid::SolidError& err)
        {
            FatalIOErrorInFunction(d)
                << "Restart from t = " << runTime.timeName() << " s"
                << " cannot continue " << h5 << ": " << err.what() << nl
                << "    Nothing was changed. Restore this run's solid.h5,"
                << " restart from another time, or start anew (startFrom"
                << " startTime, -overwrite)" << exit(FatalIOError);
        }
    }

    // h5Step checked against the step's time in the file before any step
    // is removed (an edited h5Step would cut the file)
    const label k = solidDomain::restartStep(runTime);
    const clockTime timer;
    label removed = 0;
    try
    {
        removed = solid::truncateSteps(h5, k + 1);
    }
    catch (const solid::SolidError& err)
    {
        FatalErrorInFunction
            << "Restart from t = " << runTime.timeName() << " s: cannot"
            << " remove the steps after " << k << " from " << h5 << ": "
            << err.what() << exit(FatalError);
    }
    if (removed)
    {
        Info<< "Solid: removed " << removed << " steps after step " << k
            << " from " << h5 << " (written after this time by the run"
            << " that stopped; a copy of "
            << word::printf("%.1f", fileSize(h5)/1048576.0) << " MB in "
            << word::printf("%.3f", timer.elapsedTime()) << " s)" << endl;
    }
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fluidSolidInteraction::createMotion
(
    const dictionary& interfaceDict
)
{
    if (interfaceDict.found("motionDistance"))
    {
        motion_.reset
        (
            new interfaceMotion
            (
                mesh_, patchi_, fsiPatch_, interfaceDict,
                interfaceDict.getOrDefault<vector>("axisOrigin", Zero),
                map_->axisymmetric()
              ? interfaceDict.get<vector>("axisDirection") : vector(Zero)
            )
        );
        bandMotion_.reset(new bandMeshMotion(mesh_, motion_->movedPoints()));
        wallPoints_ = motion_->usedPatchPoints();
        // The probes follow the mesh once per step, after its last pass
        // (step()), not in every pass
        bandMotion_->deferFunctionObjects();
        Info<< "FSI mesh motion: geometry updated on " << bandMotion_->nFaces()
            << " faces and " << bandMotion_->nCells() << " cells of "
            << mesh_.nFaces() << " and " << mesh_.nCells()
            << (bandMotion_->banded() ? "" : " (whole mesh: a coupled patch"
                " touches them)") << endl;
        {
            // What a coupling pass after the first of a step can change
            // (issue 18 item 5: passes 2+ on these cells only)
            const label nStages = fluid_.rk().nStages();
            Info<< "FSI mesh motion: a repeated coupling pass can change "
                << bandMotion_->nCellsWithin(2*nStages) << " of "
                << mesh_.nCells() << " cells (the band's and "
                << 2*nStages << " face layers: " << nStages
                << " Runge-Kutta stages of a two-layer stencil)" << endl;
        }
        return;
    }

    if (!mesh_.foundObject<pointVectorField>("pointDisplacement"))
    {
        FatalErrorInFunction
            << "The fluid mesh has no pointDisplacement field: use"
            << " dynamicMotionSolverFvMesh with a displacement motion solver"
            << " (e.g. displacementLaplacian) in constant/dynamicMeshDict,"
            << " or interface{} motionDistance in fsiProperties"
            << exit(FatalError);
    }
    pointDisplacement_ =
        &mesh_.lookupObjectRef<pointVectorField>("pointDisplacement");
    wallPoints_ = fsiPatch_.localToGlobal();
    if (!pointDisplacement_->boundaryField()[patchi_].fixesValue())
    {
        FatalErrorInFunction
            << "pointDisplacement on the FSI patch "
            << mesh_.boundaryMesh()[patchi_].name()
            << " must be a fixedValue type (set by the coupling)"
            << exit(FatalError);
    }
}


void Foam::fluidSolidInteraction::readState()
{
    const Time& runTime = mesh_.time();
    const fileName stateFile
    (
        runTime.timePath()/"uniform"/foamTools::uniformState::fsiState()
    );
    if (!isFile(stateFile))
    {
        FatalErrorInFunction
            << "Restart from t = " << runTime.timeName() << " s: no "
            << stateFile << " (the run stopped while writing this time?"
            << " Start from the previous write time)" << exit(FatalError);
    }
    IFstream is(stateFile);
    const dictionary d(is);
    const scalarField d0(d.get<scalarField>("fluidInterfaceDisplacement"));
    if (d0.size() != fluidInterfaceDisplacement_.size())
    {
        FatalIOErrorInFunction(d)
            << "fluidInterfaceDisplacement has " << d0.size()
            << " values, the interface " << fluidInterfaceDisplacement_.size()
            << exit(FatalIOError);
    }
    fluidInterfaceDisplacement_ = d0;
    wallWork_ = d.get<scalar>("wallWork");
    coupling_->readState(d);
    Info<< "FSI: restarted the interface displacement and the coupling"
        << " statistics from " << stateFile << endl;
}


void Foam::fluidSolidInteraction::checkMap() const
{
    // A uniform unit pressure on the fluid patch (force Sf on the solid):
    // the solid nodal forces must add up to the fluid force (full ring in
    // r-z; tests/blast/mapCheck.sh)
    const vectorField Sf
    (
        fsiPatch_.faceValues(mesh_.Sf().boundaryField()[patchi_])
    );
    const scalarField f(map_->nodalForces(Sf));
    vector sumF(Zero);
    const label dim = solid_->mesh().dim();
    forAll(f, i) sumF[i % dim] += f[i];
    const vector fluidF(map_->ringForce(Sf));
    Info<< "FSI map check: unit pressure, fluid force "
        << (map_->axisymmetric() ? "(full ring, (r z 0)) " : "")
        << fluidF << " N, solid nodal force " << sumF
        << " N, relative difference "
        << mag(fluidF - sumF)/max(mag(fluidF), VSMALL) << endl;
}


void Foam::fluidSolidInteraction::openLog()
{
    if (!Pstream::master())
    {
        return;
    }
    couplingLog_ = foamTools::runLogFiles::openLog
    (
        mesh_.time(),
        "fsi",
        foamTools::runLogFiles::couplingName(),
        foamTools::runLogFiles::couplingHeader()
    );
    couplingLog_() << coupling_->type()
        << ")" << nl
        << "# time [s]  dt [s]  iterations  residual [-]  converged"
        << "  interfaceForce (x y z) [N]  interfaceVelocityMax [m/s]"
        << "  gclError [-]  fluidWallWork [J]  solidExternalWork [J]" << nl;
}


void Foam::fluidSolidInteraction::moveWall(const scalarField& d)
{
    // At the points the motion reads (on 2 ranks about half of them and
    // their neighbourhood, not the whole interface on each)
    const vectorField wallDisplacement(map_->pointValues(d, wallPoints_));
    if (motion_.valid())
    {
        bandMotion_->movePoints(motion_->newPoints(wallDisplacement));
    }
    else
    {
        pointDisplacement_->boundaryFieldRef()[patchi_] ==
            fsiPatch_.localPointValues(wallDisplacement);
        mesh_.update();
    }
}


void Foam::fluidSolidInteraction::zeroWedgeSpeeds()
{
    // Axisymmetry: the swirl is removed in the ALE stages, and the thin
    // cells at the axis (width r theta) would otherwise set the time step
    surfaceScalarField& amaxSf = fluid_.amaxSf();
    forAll(mesh_.boundary(), patchi)
    {
        if (isA<wedgeFvPatch>(mesh_.boundary()[patchi]))
        {
            amaxSf.boundaryFieldRef()[patchi] = Zero;
        }
    }
}


void Foam::fluidSolidInteraction::wallFaceValues
(
    const vectorField& localViscousForce,
    vectorField& force,
    vectorField& viscousForce,
    vectorField& Sf,
    scalarField& Z
) const
{
    // Packed face by face: force (3), Sf (3), Z (1), with the viscous
    // stress also the viscous force (3)
    const bool viscous = fluid_.viscous();
    const label width = viscous ? 10 : 7;
    const vectorField& phiU = fluid_.phiU().boundaryField()[patchi_];
    const vectorField& patchSf = mesh_.boundary()[patchi_].Sf();
    const rhoEThermo& thermo = fluid_.thermo();
    const scalarField rhoc
    (
        thermo.rho().boundaryField()[patchi_].patchInternalField()
       *thermo.c().boundaryField()[patchi_].patchInternalField()
    );
    scalarField local(width*phiU.size());
    forAll(phiU, facei)
    {
        scalar* v = &local[width*facei];
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            v[d] = phiU[facei][d];
            v[3 + d] = patchSf[facei][d];
        }
        v[6] = rhoc[facei];
        if (viscous)
        {
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                v[7 + d] = localViscousForce[facei][d];
            }
        }
    }
    const scalarField all(fsiPatch_.packedFaceValues(local, width));
    const label n = fsiPatch_.size();
    force.setSize(n);
    viscousForce.setSize(viscous ? n : 0);
    Sf.setSize(n);
    Z.setSize(n);
    for (label facei = 0; facei < n; ++facei)
    {
        const scalar* v = &all[width*facei];
        force[facei] = vector(v[0], v[1], v[2]);
        Sf[facei] = vector(v[3], v[4], v[5]);
        Z[facei] = v[6];
        if (viscous)
        {
            viscousForce[facei] = vector(v[7], v[8], v[9]);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fluidSolidInteraction::fluidSolidInteraction
(
    dynamicFvMesh& mesh,
    conservativeFluid& fluid
)
:
    mesh_(mesh),
    fluid_(fluid),
    fsiProperties_
    (
        IOobject
        (
            "fsiProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    patchi_
    (
        interfacePatchIndex(mesh, checkedInterfaceDict(fsiProperties_))
    ),
    fsiPatch_(mesh.boundaryMesh()[patchi_]),
    pointDisplacement_(nullptr),
    solidSubcycles_
    (
        fsiRanges::readOrDefault<label>
        (
            foamTools::subDict(fsiProperties_, "coupling"), "coupling",
            "solidSubcycles", 1
        )
    ),
    wallWork_(0),
    courantRate_(-1),
    cpuMotion_(0),
    cpuFluid_(0),
    cpuSolid_(0),
    cpuCoupling_(0),
    cpuRestore_(0),
    cpuOutput_(0),
    cpuStart_(0)
{
    const Time& runTime = mesh_.time();
    const dictionary& interfaceDict =
        foamTools::subDict(fsiProperties_, "interface");

    // The coupling's and the mesh motion's entries checked before any
    // output is created or cut (adv37 w98: maxIter 0 refused after
    // solid.h5, solid.xmf and the logs were written, the corrected run
    // then refused as one over results)
    coupling_ =
        couplingScheme::New(foamTools::subDict(fsiProperties_, "coupling"));
    if (interfaceDict.found("motionDistance"))
    {
        scalar motionDistance = 0;
        label motionNearest = 0;
        interfaceMotion::checkEntries
        (
            interfaceDict, motionDistance, motionNearest
        );
    }

    if (runTime.value() > 0)
    {
        truncateSolidResults(runTime);
    }

    solid_.reset(new solidDomain(runTime));

    map_.reset
    (
        new interfaceMap
        (
            fsiPatch_,
            solid_->mesh(),
            interfaceDict,
            solid_->fixedDofs()
        )
    );

    // r-z: a solid interface finer than the fluid's has displacement
    // patterns that vanish at every fluid patch point. The fluid neither
    // loads nor damps them, the cell's shear moduli (1e-7 of its bulk
    // modulus) hardly resist them, and they grow into a sawtooth along the
    // membrane that spoils the strains inside (docs/results/
    // blastPlaneWave.md, "Unseen interface modes"). Refused.
    if (map_->mapType() == "faces")
    {
        scalar sigmaRatio = 1;
        const label nUnseen =
            map_->unseenModes(solid_->fixedDofs(), sigmaRatio);
        if (nUnseen)
        {
            FatalIOErrorInFunction(interfaceDict)
                << "the solid face set "
                << interfaceDict.get<word>("solidFaceSet") << " ("
                << map_->nodes().size() << " nodes) is finer than the fluid"
                << " patch " << fsiPatch_.name() << " (" << fsiPatch_.size()
                << " faces): " << nUnseen << " displacement patterns of the"
                << " solid interface vanish at every fluid patch point, so"
                << " the fluid neither loads nor damps them. Refine the fluid"
                << " at the interface (the blast tutorials' Allrun -h) or"
                << " coarsen the solid's interface faces (-cell) so that"
                << " every solid face holds fluid patch points"
                << exit(FatalIOError);
        }
        Info<< "FSI interface: the fluid patch points see every solid"
            << " interface displacement pattern (smallest/largest singular"
            << " value of their weights " << sigmaRatio << ")" << endl;
    }

    // Restart: the mesh (built on the reference points, newMesh) to the
    // points of the start time
    if (runTime.value() > 0)
    {
        mesh_.movePoints
        (
            pointIOField
            (
                IOobject
                (
                    "points",
                    runTime.timeName(),
                    polyMesh::meshSubDir,
                    mesh_,
                    IOobject::MUST_READ,
                    IOobject::NO_WRITE,
                    false
                )
            )
        );
    }

    solid_->couple(map_->nodes());
    Info<< "Solid: " << solid_->mesh().nElements() << " elements, stable"
        << " time step x explicitSafety " << solid_->timeStep() << " s"
        << endl;
    if (solidSubcycles_ > 1)
    {
        Info<< "FSI: solidSubcycles " << solidSubcycles_ << ": the coupled"
            << " step up to " << solidSubcycles_ << " solid steps ("
            << solidSubcycles_*solid_->timeStep() << " s now)" << endl;
    }

    createMotion(interfaceDict);

    fluidInterfaceDisplacement_ = map_->interfaceDofs(solid_->displacement());
    if (runTime.value() > 0)
    {
        readState();
    }

    interfaceMass_ = map_->interfaceDofs(solid_->lumpedMass());

    checkMap();

    openLog();

    cpuStart_ = runTime.elapsedCpuTime();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fluidSolidInteraction::step()
{
    const Time& runTime = mesh_.time();
    const scalar dt = runTime.deltaTValue();
    const interfaceMap& map = map_();
    solidDomain& solid = solid_();

    // Start of the step on both sides
    cpuTimer_.cpuTimeIncrement();
    fluid_.storeOldState();
    solid.save();
    cpuRestore_ += cpuTimer_.cpuTimeIncrement();

    const scalarField v0(map.interfaceDofs(solid.velocity()));

    const string hint
    (
        "FSI: coupling scheme " + coupling_->type()
      + " (a coupling that diverges ends here too: explicitStaggered"
        " is unstable for a solid much lighter than water,"
        " docs/results/blastCoupling.md; robin is the stable default)"
    );

    coupling_->beginStep();
    // The first guess (coupling{} predictor): central difference, x = v_n
    // + dt/2 a_n, or the acceleration extrapolated in time
    scalarField x
    (
        coupling_->predict(v0, map.interfaceDofs(solid.acceleration()), dt)
    );
    scalar gclError = 0;
    // The viscous force on this rank's wall faces, summed (coupling.dat)
    vector viscousF(Zero);
    bool done = false;
    while (!done)
    {
        cpuCoupling_ += cpuTimer_.cpuTimeIncrement();
        if (coupling_->iterations() > 0)
        {
            fluid_.restoreOldState();
            solid.restore();
        }
        cpuRestore_ += cpuTimer_.cpuTimeIncrement();

        // Fluid wall to d_n + dt x, mesh motion
        moveWall(fluidInterfaceDisplacement_ + dt*x);
        cpuMotion_ += cpuTimer_.cpuTimeIncrement();

        gclError = fluid_.aleStep(dt, hint);

        // Wall force at t_n+1 -> solid nodes (the interface patch's fluxes
        // only: a full evaluation costs as much as a Runge-Kutta stage),
        // with the area vectors of the moved interface faces (the pressure
        // load and the Robin impedance) and the fluid's acoustic impedance
        // at the wall (Robin), over the whole patch in one exchange
        // With the viscous stress, its force on the wall too (the
        // tangential traction of the no-slip wall and the normal viscous
        // stress): mapped conservatively onto the solid nodes for either
        // load, added to the pressure's (docs/theory/fsi.md, "The
        // viscous traction")
        fluid_.wallFluxes(patchi_);
        const vectorField localViscousForce
        (
            fluid_.wallViscousForce(patchi_)
        );
        viscousF = sum(localViscousForce);
        vectorField wallForce;
        vectorField viscousForce;
        vectorField wallSf;
        scalarField Z;
        wallFaceValues(localViscousForce, wallForce, viscousForce, wallSf, Z);
        cpuFluid_ += cpuTimer_.cpuTimeIncrement();
        scalarField load
        (
            map.pressureLoad()
          ? map.nodalPressureForces
            (
                wallForce,
                wallSf,
                fluidInterfaceDisplacement_ + dt*x
            )
          : map.nodalForces(wallForce)
        );
        if (viscousForce.size())
        {
            load += map.nodalForces(viscousForce);
        }
        solid.advance(load, runTime.value());
        cpuSolid_ += cpuTimer_.cpuTimeIncrement();

        const scalarField xTilde(0.5*(v0 + map.interfaceDofs(solid.velocity())));

        // Acoustic added damping of the fluid per interface dof (Robin)
        const scalarField beta
        (
            0.25*dt*map.nodalImpedance(Z, wallSf)/interfaceMass_
        );

        done = coupling_->update(x, xTilde, beta);

        Info<< "FSI iteration " << coupling_->iterations() << ": residual "
            << coupling_->residual() << endl;
    }
    cpuCoupling_ += cpuTimer_.cpuTimeIncrement();
    if (bandMotion_.valid())
    {
        // The function objects (probes) to the step's final mesh
        bandMotion_->notifyFunctionObjects();
        cpuMotion_ += cpuTimer_.cpuTimeIncrement();
    }
    coupling_->endStep(runTime.value());
    fluidInterfaceDisplacement_ += dt*x;

    // The fluid's work on its wall over the step, trapezoidal in time as
    // the solid's (the same rule on the linear load over its substeps)
    wallWork_ +=
        0.5*sum((solid.startForces() + solid.interfaceForces())*dt*x);

    // Signal speeds of the final state for the next step's Courant number
    cpuCoupling_ += cpuTimer_.cpuTimeIncrement();
    fluid_.signalSpeeds();
    zeroWedgeSpeeds();
    const scalar localRate = fluid_.localCourantRate();
    cpuFluid_ += cpuTimer_.cpuTimeIncrement();

    // The step's values in one exchange (each exchange a point where the
    // ranks wait for each other): the Courant rate and the geometric
    // conservation error (largest over the ranks), the wall force (summed
    // in rank order, as gSum on 2 ranks: the same bits) and the solid's
    // output of the step (its probes' element samples from their owners,
    // the interface maxima), written by write()
    vector F = sum(fluid_.phiU().boundaryField()[patchi_]) + viscousF;
    {
        stepValues_.clear();
        const scalar maxima[2] = {localRate, gclError};
        const std::size_t iMax = stepValues_.max(maxima, 2);
        const std::size_t iSum = stepValues_.sum(F.cdata(), 3);
        solid.packOutput(stepValues_);
        solid.model().partition().combine(stepValues_);
        courantRate_ = stepValues_[iMax];
        gclError = stepValues_[iMax + 1];
        F = vector
        (
            stepValues_[iSum], stepValues_[iSum + 1], stepValues_[iSum + 2]
        );
    }
    if (couplingLog_.valid())
    {
        couplingLog_()
            << runTime.value() << ' ' << dt << ' '
            << coupling_->iterations() << ' ' << coupling_->residual() << ' '
            << coupling_->converged() << ' ' << F.x() << ' ' << F.y() << ' '
            << F.z() << ' ' << max(mag(x)) << ' ' << gclError << ' '
            << wallWork_ << ' ' << solid.energy().externalWork << nl;
        // Complete rows up to the last step after a FatalError stop too
        couplingLog_().flush();
        foamTools::runLogFiles::checkWritten(couplingLog_());
    }
    cpuOutput_ += cpuTimer_.cpuTimeIncrement();
}


void Foam::fluidSolidInteraction::setDeltaT()
{
    Time& runTime = const_cast<Time&>(mesh_.time());
    const dictionary& controlDict = runTime.controlDict();

    const bool adjustTimeStep =
        controlDict.lookupOrDefault("adjustTimeStep", false);
    const scalar maxCo = controlDict.lookupOrDefault<scalar>("maxCo", 1.0);
    const scalar maxDeltaT =
        controlDict.lookupOrDefault<scalar>("maxDeltaT", GREAT);
    // also as modified during the run (runTimeModifiable)
    foamTools::checkTimeControls(runTime, adjustTimeStep, maxCo, maxDeltaT);

    // The Courant number of the state the last step ended with (reduced
    // over the ranks with the step's other global values); before the
    // first step from the initial fluxes
    const scalar stepDeltaT0 = runTime.deltaTValue();
    if (courantRate_ < 0)
    {
        zeroWedgeSpeeds();
        courantRate_ =
            returnReduce(fluid_.localCourantRate(), maxOp<scalar>());
    }
    const scalar CoNum = fluid_.courantNumber(stepDeltaT0, courantRate_);
    courantRate_ = -1;

    // writeControl adjustableRunTime: the step shortened so that steps end
    // on the next write time, as Time::adjustDeltaT does, but with the
    // write intervals counted from t = 0. OpenFOAM counts them from the
    // start time of the run (and takes that from the directory name), so a
    // restarted run would round differently and its steps, hence all its
    // results, would differ from the uninterrupted run's in the last bits;
    // counted from t = 0 the restart is bitwise (tests/blast/restart.sh)
    const bool adjustToWrites =
        controlDict.getOrDefault<word>("writeControl", "timeStep")
     == "adjustableRunTime";
    const scalar writeInterval = adjustToWrites
      ? controlDict.get<scalar>("writeInterval")
      : 0;
    const label writeIndex = adjustToWrites
      ? label((runTime.value() + 0.5*runTime.deltaTValue())/writeInterval)
      : 0;
    // atMost: dt is a limit (the solid's), the steps to the write time
    // rounded up so that they stay within it (rounded to the nearest, a
    // step up to 1.5 dt: 2 solid substeps where 1 was meant)
    const auto setDeltaT = [&](const scalar dt, const bool atMost)
    {
        scalar newDt = dt;
        const scalar toNextWrite =
            max(0.0, (writeIndex + 1)*writeInterval - runTime.value());
        const scalar nSteps = toNextWrite/dt;
        if (adjustToWrites && nSteps < labelMax)
        {
            const scalar even = toNextWrite
               /max(1, atMost ? std::ceil(nSteps) : round(nSteps));
            newDt = even >= dt ? min(even, 2*dt) : max(even, 0.2*dt);
        }
        runTime.setDeltaT(newDt, false);
    };

    // As OpenFOAM's setDeltaT.H, with the step above
    if (adjustTimeStep)
    {
        const scalar maxDeltaTFact = maxCo/(CoNum + SMALL);
        const scalar deltaTFact =
            min(min(maxDeltaTFact, 1.0 + 0.1*maxDeltaTFact), 1.2);
        setDeltaT(min(deltaTFact*runTime.deltaTValue(), maxDeltaT), false);
        Info<< "deltaT = " <<  runTime.deltaTValue() << endl;
    }

    const scalar solidDt = solidSubcycles_*solid_->timeStep();
    if (runTime.deltaTValue() > solidDt)
    {
        setDeltaT(solidDt, true);
    }

    // A fixed deltaT (within the solid's limit) above the stability limit
    // stops before the step (adv32 pr22, pr24)
    foamTools::checkCourantNumber
    (
        runTime,
        adjustTimeStep,
        CoNum*runTime.deltaTValue()/max(stepDeltaT0, VSMALL)
    );
}


void Foam::fluidSolidInteraction::write(const scalar stepDeltaT)
{
    cpuTimer_.cpuTimeIncrement();
    // Charged to output however write() returns
    struct charge
    {
        cpuTime& timer;
        scalar& sum;
        ~charge() { sum += timer.cpuTimeIncrement(); }
    } chargeOutput{cpuTimer_, cpuOutput_};

    // The solid's rows from the values step() combined
    solid_->write(stepValues_, stepDeltaT);

    const Time& runTime = mesh_.time();
    if (!runTime.writeTime())
    {
        return;
    }

    // Renamed into place: complete or absent
    const fileName file
    (
        runTime.timePath()/"uniform"/foamTools::uniformState::fsiState()
    );
    {
        OFstream os(file + ".tmp");
        os.precision(17);
        os.writeEntry("fluidInterfaceDisplacement", fluidInterfaceDisplacement_);
        os.writeEntry("wallWork", wallWork_);
        coupling_->writeState(os);
    }
    mv(file + ".tmp", file);

    // The coupling log on disk up to this time: a run continued from this
    // time writes its own (postProcessing/fsi/<this time>), which then
    // starts where this one is complete
    if (couplingLog_.valid())
    {
        couplingLog_().flush();
        foamTools::runLogFiles::checkWritten(couplingLog_());
    }
}


void Foam::fluidSolidInteraction::report()
{
    coupling_->report(Info);

    // The interface energy balance: the solid's external work is that of
    // the interface load (its other prescribed dofs are fixed at zero)
    const scalar solidWork = solid_->energy().externalWork;
    const scalar balance =
        mag(wallWork_ - solidWork)
       /max(max(mag(wallWork_), mag(solidWork)), VSMALL);
    Info<< "FSI interface energy: work of the fluid on the wall "
        << wallWork_ << " J, external work of the solid " << solidWork
        << " J, relative difference " << balance << " [-]" << endl;

    // The parts of the time loop; "other": the time-step control, the
    // state checks and the function objects (probes)
    // (to 0.01 s: the clock's resolution, not the stream's 17 digits)
    const auto sec = [](const scalar x)
    {
        char buf[32];
        std::snprintf(buf, sizeof(buf), "%.2f", x);
        return word(buf);
    };
    const scalar total = mesh_.time().elapsedCpuTime() - cpuStart_;
    const scalar other = total - cpuMotion_ - cpuFluid_ - cpuSolid_;
    Info<< "CPU time of the time loop " << sec(total) << " s: mesh motion "
        << sec(cpuMotion_) << " s, fluid " << sec(cpuFluid_) << " s, solid "
        << sec(cpuSolid_) << " s, other " << sec(other) << " s (coupling "
        << sec(cpuCoupling_) << " s, restore " << sec(cpuRestore_)
        << " s, output " << sec(cpuOutput_) << " s, time-step control,"
        << " checks and function objects "
        << sec(other - cpuCoupling_ - cpuRestore_ - cpuOutput_)
        << " s)" << endl;
    if (fluid_.viscous())
    {
        Info<< "    of the fluid's, the viscous stress "
            << sec(fluid_.viscousCpuTime()) << " s (the stages' terms and"
            << " the wall's viscous force)" << endl;
    }
    if (bandMotion_.valid() && bandMotion_->nUpdates())
    {
        // The band updates (this rank's): the faces whose points changed
        // bit for bit are recomputed, the others keep their geometry
        Info<< "FSI mesh motion: " << bandMotion_->nUpdates()
            << " band updates, " << bandMotion_->nUnchangedUpdates()
            << " without a changed point; faces recomputed per update "
            << bandMotion_->nFaceUpdates()/bandMotion_->nUpdates()
            << " of " << bandMotion_->nFaces() << endl;
    }
    if (Pstream::parRun())
    {
        // The slowest rank of each part: a rank's waiting for the others
        // shows in the part holding the next exchange (the coupling's
        // gathers, the fluid's processor patches)
        const auto largest = [](const scalar x)
        {
            return returnReduce(x, maxOp<scalar>());
        };
        Info<< "    largest over the " << Pstream::nProcs() << " ranks:"
            << " time loop " << sec(largest(total)) << " s, mesh motion "
            << sec(largest(cpuMotion_)) << " s, fluid "
            << sec(largest(cpuFluid_)) << " s, solid "
            << sec(largest(cpuSolid_)) << " s, other "
            << sec(largest(total - cpuMotion_ - cpuFluid_ - cpuSolid_))
            << " s" << endl;
        // Every rank's split (the imbalance of a part: one rank's work
        // against the other's waiting in it)
        List<scalarList> split(Pstream::nProcs());
        split[Pstream::myProcNo()] = scalarList
        ({
            total, cpuMotion_, cpuFluid_, cpuSolid_, cpuCoupling_,
            cpuRestore_, cpuOutput_
        });
        Pstream::gatherList(split);
        forAll(split, proci)
        {
            const scalarList& x = split[proci];
            if (x.size() != 7) continue;
            Info<< "    rank " << proci << ": time loop " << sec(x[0])
                << " s: mesh motion " << sec(x[1]) << " s, fluid "
                << sec(x[2]) << " s, solid " << sec(x[3]) << " s, other "
                << sec(x[0] - x[1] - x[2] - x[3]) << " s (coupling "
                << sec(x[4]) << " s, restore " << sec(x[5]) << " s, output "
                << sec(x[6]) << " s, the rest "
                << sec(x[0] - x[1] - x[2] - x[3] - x[4] - x[5] - x[6])
                << " s)" << endl;
        }
    }

    if (couplingLog_.valid())
    {
        couplingLog_() << "# ";
        coupling_->report(couplingLog_());
    }
}


// ************************************************************************* //
