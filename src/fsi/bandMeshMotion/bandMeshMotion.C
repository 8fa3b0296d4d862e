#include "bandMeshMotion.H"
#include "bandFaceGeometry.H"
#include "bitSet.H"
#include "pointIOField.H"
#include "labelIOList.H"
#include "MeshObject.H"
#include "pointMesh.H"
#include "lduMesh.H"
#include "processorPolyPatch.H"
#include "volFields.H"
#include "surfaceFields.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{

//- The mesh's interpolation factors, writable (surfaceInterpolation hands
//  them out const)
struct interpolationFactors
{
    surfaceScalarField& w;
    surfaceScalarField& dc;
    surfaceScalarField& nodc;
    surfaceVectorField& corr;

    explicit interpolationFactors(const fvMesh& mesh)
    :
        w(const_cast<surfaceScalarField&>(mesh.weights())),
        dc(const_cast<surfaceScalarField&>(mesh.deltaCoeffs())),
        nodc(const_cast<surfaceScalarField&>(mesh.nonOrthDeltaCoeffs())),
        corr
        (
            const_cast<surfaceVectorField&>(mesh.nonOrthCorrectionVectors())
        )
    {}
};

//- The patch of each face of a list (-1: an internal face)
static labelList patchOf(const polyMesh& mesh, const labelUList& faceLabels)
{
    const polyBoundaryMesh& pbm = mesh.boundaryMesh();
    labelList patches(faceLabels.size(), -1);
    forAll(faceLabels, i)
    {
        if (faceLabels[i] >= mesh.nInternalFaces())
        {
            patches[i] = pbm.whichPatch(faceLabels[i]);
        }
    }
    return patches;
}

} // End namespace Foam


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::bandMeshMotion::storeOldGeometry()
{
    // polyMesh::movePoints: the old points are the points at the first
    // motion of a time step (only the band's differ)
    pointField& oldPoints = const_cast<pointField&>(mesh_.oldPoints());
    const pointField& points = mesh_.points();
    for (const label pointi : points_)
    {
        oldPoints[pointi] = points[pointi];
    }

    // fvMesh::storeOldVol: V00 <- V0 <- V (only the band's cells differ)
    const scalarField& V = mesh_.V();
    scalarField& V0 = mesh_.setV0();
    typedef DimensionedField<scalar, volMesh> volInternal;
    if (mesh_.foundObject<volInternal>("V00"))
    {
        scalarField& V00 = const_cast<volInternal&>(mesh_.V00());
        for (const label celli : cells_)
        {
            V00[celli] = V0[celli];
        }
    }
    for (const label celli : cells_)
    {
        V0[celli] = V[celli];
    }

    // fvMesh::movePoints: the old-time mesh flux
    surfaceScalarField& phi = const_cast<surfaceScalarField&>(mesh_.phi());
    if (phi.timeIndex() != mesh_.time().timeIndex())
    {
        phi.oldTime();
    }
}


void Foam::bandMeshMotion::updateGeometry(const pointField& newPoints)
{
    const Time& runTime = mesh_.time();

    // The points, written at the next write time as polyMesh::movePoints
    // sets them to be
    // (polyMesh::points is its pointIOField points_)
    pointIOField& points =
        const_cast<pointIOField&>
        (
            static_cast<const pointIOField&>(mesh_.points())
        );

    // Everything is recomputed at the first band update and after a
    // motion past this object (polyMesh::movePoints restamps the points'
    // event number); else only what a changed point reaches
    const bool all = centresEvent_ == -1 || centresEvent_ != points.eventNo();
    const bool newStep = oldCentresIndex_ != runTime.timeIndex();

    // face::centre of the band's faces at the step's start (the old
    // points, fixed within a step): at the first update of a step, the
    // centres of the last update if the points are still those it left,
    // else computed from the old points
    const faceList& faces = mesh_.faces();
    const pointField& oldPoints = mesh_.oldPoints();
    if (newStep)
    {
        if (!all)
        {
            // (a copy: the faces left alone keep their new centres)
            oldCentres_ = newCentres_;
        }
        else
        {
            oldCentres_.setSize(faces_.size());
            forAll(faces_, i)
            {
                oldCentres_[i] =
                    bandFaceGeometry::centre(faces[faces_[i]], oldPoints);
            }
            newCentres_.setSize(faces_.size());
        }
        oldCentresIndex_ = runTime.timeIndex();
    }

    // The band points whose old or new position changes (bit for bit): a
    // face's geometry and swept volume are functions of its old and new
    // points only, so a face none of whose points changed keeps them, a
    // cell none of whose faces changed its centre and volume, a face
    // between two such cells its interpolation factors (the same
    // operations on the same bits). At a new step the old points are the
    // last update's points: they change where those differed from the
    // last step's old points.
    changedPoints_.reset();
    label nChanged = 0;
    for (const label pointi : points_)
    {
        const bool changed =
            all
         || !bandFaceGeometry::sameBits(newPoints[pointi], points[pointi])
         || (newStep && movedInStep_.test(pointi));
        if (changed)
        {
            changedPoints_.set(pointi);
            ++nChanged;
        }
        points[pointi] = newPoints[pointi];
        movedInStep_.set
        (
            pointi,
            !bandFaceGeometry::sameBits(points[pointi], oldPoints[pointi])
        );
    }
    ++nUpdates_;
    if (!nChanged)
    {
        ++nUnchangedUpdates_;
    }

    points.writeOpt() = IOobject::AUTO_WRITE;
    points.instance() = runTime.timeName();
    points.eventNo() = mesh_.getEvent();
    if (mesh_.foundObject<labelIOList>("tetBasePtIs"))
    {
        labelIOList& tetBasePtIs =
            const_cast<labelIOList&>(mesh_.tetBasePtIs());
        tetBasePtIs.writeOpt() = IOobject::AUTO_WRITE;
        tetBasePtIs.instance() = runTime.timeName();
        tetBasePtIs.eventNo() = mesh_.getEvent();
    }

    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    const label nInternal = mesh_.nInternalFaces();
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();

    // Per face of the band whose points changed: the swept volume since
    // the start of the step (face::sweptVol(oldPoints, points)) ->
    // meshPhi, the face centre and area vector
    // (primitiveMesh::makeFaceCentresAndAreas), |Sf|. (A face left alone
    // keeps its meshPhi: within a step deltaT is the same, and at the
    // first update of a step its old points are its points, so its swept
    // volume is a zero and meshPhi that zero over any deltaT.)
    const scalar rDeltaT = 1.0/runTime.deltaTValue();
    surfaceScalarField& phi = const_cast<surfaceScalarField&>(mesh_.phi());
    scalarField& phii = phi.primitiveFieldRef();
    surfaceScalarField::Boundary& phibf = phi.boundaryFieldRef();
    vectorField& fCtrs = const_cast<vectorField&>(mesh_.faceCentres());
    vectorField& fAreas = const_cast<vectorField&>(mesh_.faceAreas());
    surfaceScalarField& magSf =
        const_cast<surfaceScalarField&>(mesh_.magSf());
    scalarField& magSfi = magSf.primitiveFieldRef();
    surfaceScalarField::Boundary& magSfbf = magSf.boundaryFieldRef();
    changedCells_.reset();
    label nFacesChanged = 0;

    // Every band point changed (the band moving): no test per face, cell
    // or factor
    const bool every = all || nChanged == points_.size();

    // meshPhi, |Sf| and the changed cells of a moved face
    auto moved = [&](const label i, const scalar sweptVol)
    {
        const label facei = faces_[i];
        if (!every)
        {
            changedCells_.set(own[facei]);
            if (facei < nInternal)
            {
                changedCells_.set(nei[facei]);
            }
        }
        const scalar swept = sweptVol*rDeltaT;
        const scalar m = mag(fAreas[facei]) + VSMALL;
        if (facei < nInternal)
        {
            phii[facei] = swept;
            magSfi[facei] = m;
        }
        else
        {
            const label patchi = facePatch_[i];
            const label pfi = facei - pbm[patchi].start();
            if (phibf[patchi].size())
            {
                phibf[patchi][pfi] = swept;
            }
            if (magSfbf[patchi].size())
            {
                magSfbf[patchi][pfi] = m;
            }
        }
        ++nFacesChanged;
    };

    // Quadrilaterals two at a time (bandFaceGeometry::moveQuadPair: each
    // lane moveFace's operations), the others one by one
    label waiting = -1;
    forAll(faces_, i)
    {
        const label facei = faces_[i];
        const face& f = faces[facei];
        if (!every)
        {
            bool changed = false;
            for (label k = 0; !changed && k < f.size(); ++k)
            {
                changed = changedPoints_.test(f[k]);
            }
            if (!changed)
            {
                continue;
            }
        }
        if (f.size() != 4)
        {
            scalar sweptVol;
            bandFaceGeometry::moveFace
            (
                f, oldPoints, points, oldCentres_[i],
                newCentres_[i], sweptVol, fCtrs[facei], fAreas[facei]
            );
            moved(i, sweptVol);
        }
        else if (waiting < 0)
        {
            waiting = i;
        }
        else
        {
            const label j[2] = {waiting, i};
            const face& fw = faces[faces_[waiting]];
            const bandFaceGeometry::facePoints<4> O[2] =
                {{fw, oldPoints}, {f, oldPoints}};
            const bandFaceGeometry::facePoints<4> P[2] =
                {{fw, points}, {f, points}};
            const point cOld[2] = {oldCentres_[waiting], oldCentres_[i]};
            point cNew[2];
            scalar sweptVol[2];
            vector fCtr[2], fArea[2];
            bandFaceGeometry::moveQuadPair
            (
                O, P, cOld, cNew, sweptVol, fCtr, fArea
            );
            for (label l = 0; l < 2; ++l)
            {
                newCentres_[j[l]] = cNew[l];
                fCtrs[faces_[j[l]]] = fCtr[l];
                fAreas[faces_[j[l]]] = fArea[l];
                moved(j[l], sweptVol[l]);
            }
            waiting = -1;
        }
    }
    if (waiting >= 0)
    {
        const label facei = faces_[waiting];
        scalar sweptVol;
        bandFaceGeometry::moveFace
        (
            faces[facei], oldPoints, points, oldCentres_[waiting],
            newCentres_[waiting], sweptVol, fCtrs[facei], fAreas[facei]
        );
        moved(waiting, sweptVol);
    }
    nFaceUpdates_ += nFacesChanged;
    centresEvent_ = points.eventNo();

    // Cell centres and volumes: primitiveMesh::makeCellCentresAndVols per
    // cell, its owned faces first, then its neighbour faces
    {
        typedef Vector<solveScalar> solveVector;
        vectorField& cellCtrs = const_cast<vectorField&>(mesh_.cellCentres());
        scalarField& cellVols = const_cast<scalarField&>(mesh_.cellVolumes());
        forAll(cells_, i)
        {
            const label celli = cells_[i];
            if (!every && !changedCells_.test(celli))
            {
                continue;
            }
            const labelList& cf = cellFaces_[i];

            solveVector cEst = Zero;
            for (const label facei : cf)
            {
                cEst += solveVector(fCtrs[facei]);
            }
            cEst /= cf.size();

            solveVector ctr = Zero;
            solveScalar vol = 0.0;
            for (const label facei : cf)
            {
                const solveVector fc(fCtrs[facei]);
                const solveVector fA(fAreas[facei]);
                const solveScalar pyr3Vol =
                    own[facei] == celli ? fA & (fc - cEst) : fA & (cEst - fc);
                const solveVector pc = (3.0/4.0)*fc + (1.0/4.0)*cEst;
                ctr += pyr3Vol*pc;
                vol += pyr3Vol;
            }
            if (mag(vol) > VSMALL)
            {
                ctr /= vol;
            }
            else
            {
                ctr = cEst;
            }
            cellCtrs[celli] = ctr;
            cellVols[celli] = vol*(1.0/3.0);
        }
    }

    // Interpolation factors of the faces of the band's cells whose
    // centre or face changed (surfaceInterpolation::make*, fvPatch::delta
    // and makeWeights)
    const vectorField& C = mesh_.cellCentres();
    interpolationFactors factors(mesh_);
    auto& [w, dc, nodc, corr] = factors;
    scalarField& wi = w.primitiveFieldRef();
    scalarField& dci = dc.primitiveFieldRef();
    scalarField& nodci = nodc.primitiveFieldRef();
    vectorField& corri = corr.primitiveFieldRef();
    surfaceScalarField::Boundary& wbf = w.boundaryFieldRef();
    surfaceScalarField::Boundary& dcbf = dc.boundaryFieldRef();
    surfaceScalarField::Boundary& nodcbf = nodc.boundaryFieldRef();
    surfaceVectorField::Boundary& corrbf = corr.boundaryFieldRef();
    forAll(interpFaces_, j)
    {
        const label facei = interpFaces_[j];
        if
        (
            !every
         && !changedCells_.test(own[facei])
         && (facei >= nInternal || !changedCells_.test(nei[facei]))
        )
        {
            // (a changed face changes its owner's centre)
            continue;
        }
        const vector& Sf = fAreas[facei];
        const vector& Cf = fCtrs[facei];
        if (facei < nInternal)
        {
            const label o = own[facei];
            const label n = nei[facei];
            const scalar SfdOwn = mag(Sf & (Cf - C[o]));
            const scalar SfdNei = mag(Sf & (C[n] - Cf));
            wi[facei] = SfdNei/(SfdOwn + SfdNei);

            const vector delta = C[n] - C[o];
            const scalar magDelta = mag(delta);
            dci[facei] = 1.0/magDelta;
            const vector unitArea = Sf/magSfi[facei];
            nodci[facei] = 1.0/max(unitArea & delta, 0.05*magDelta);
            corri[facei] = unitArea - delta*nodci[facei];
        }
        else
        {
            const label patchi = interpFacePatch_[j];
            if (patchi < 0 || !wbf[patchi].size())
            {
                // A processor patch's factors need the other side's
                // geometry: updateProcessorFactors, after the exchange
                continue;
            }
            const label i = facei - pbm[patchi].start();
            const vector unitArea = Sf/magSfbf[patchi][i];
            const vector delta =
                unitArea*(unitArea & (Cf - C[own[facei]]));
            const scalar magDelta = mag(delta);
            wbf[patchi][i] = 1.0;
            dcbf[patchi][i] = 1.0/magDelta;
            nodcbf[patchi][i] = 1.0/max(unitArea & delta, 0.05*magDelta);
            corrbf[patchi][i] = Zero;
        }
    }
}


void Foam::bandMeshMotion::updateProcessorFactors()
{
    // surfaceInterpolation::makeWeights, makeDeltaCoeffs,
    // makeNonOrthDeltaCoeffs and makeNonOrthCorrectionVectors on the
    // processor patches, with the neighbour geometry just exchanged
    interpolationFactors factors(mesh_);
    auto& [w, dc, nodc, corr] = factors;
    const surfaceVectorField& Sf = mesh_.Sf();
    const surfaceScalarField& magSf = mesh_.magSf();
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    if (!Pstream::parRun())
    {
        return;
    }

    // fvMesh's sliced geometric fields keep copies, not slices, on
    // processor patches (SlicedGeometricField's preserveCouples): Sf and
    // Cf hold the patch's face areas and centres as they were made, C the
    // other side's cell centres (evaluated when it is made)
    surfaceVectorField& Sf0 = const_cast<surfaceVectorField&>(mesh_.Sf());
    surfaceVectorField& Cf0 = const_cast<surfaceVectorField&>(mesh_.Cf());
    for (const label patchi : processorPatches_)
    {
        Sf0.boundaryFieldRef()[patchi] =
            pbm[patchi].patchSlice(mesh_.faceAreas());
        Cf0.boundaryFieldRef()[patchi] =
            pbm[patchi].patchSlice(mesh_.faceCentres());
    }
    // C on the processor patches: the other side's cell centres, which
    // polyBoundaryMesh::movePoints has just received (what
    // C.correctBoundaryConditions would exchange again: the same bits, one
    // exchange less per motion)
    {
        volVectorField& C = const_cast<volVectorField&>(mesh_.C());
        for (const label patchi : processorPatches_)
        {
            C.boundaryFieldRef()[patchi] =
                refCast<const processorPolyPatch>(pbm[patchi])
               .neighbFaceCellCentres();
        }
    }

    for (const label patchi : processorPatches_)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        {
            // processorFvPatch::makeWeights (protected), the same
            // operations: the face normals point the other way on the
            // other side
            const processorPolyPatch& pp =
                refCast<const processorPolyPatch>(pbm[patchi]);
            const scalarField neighbFaceCentresCn
            (
                (
                    pp.neighbFaceAreas()
                   /(mag(pp.neighbFaceAreas()) + VSMALL)
                )
              & (pp.neighbFaceCentres() - pp.neighbFaceCellCentres())
            );
            w.boundaryFieldRef()[patchi] =
                neighbFaceCentresCn
               /((p.nf() & (p.Cf() - p.Cn())) + neighbFaceCentresCn);
        }
        const vectorField patchDeltas(p.delta());
        scalarField& dcp = dc.boundaryFieldRef()[patchi];
        scalarField& nodcp = nodc.boundaryFieldRef()[patchi];
        vectorField& corrp = corr.boundaryFieldRef()[patchi];
        forAll(p, i)
        {
            const vector& delta = patchDeltas[i];
            dcp[i] = 1.0/mag(delta);
            const vector unitArea =
                Sf.boundaryField()[patchi][i]/magSf.boundaryField()[patchi][i];
            nodcp[i] = 1.0/max(unitArea & delta, 0.05*mag(delta));
            corrp[i] = unitArea - delta*nodcp[i];
        }
    }
}


void Foam::bandMeshMotion::notify()
{
    // As polyMesh::movePoints after the geometry (on a processor patch:
    // the exchange of face centres, areas and cell centres with the
    // other side)
    const pointField& points = mesh_.points();
    const_cast<polyBoundaryMesh&>(mesh_.boundaryMesh()).movePoints(points);
    updateProcessorFactors();
    const_cast<pointZoneMesh&>(mesh_.pointZones()).movePoints(points);
    const_cast<faceZoneMesh&>(mesh_.faceZones()).movePoints(points);
    const_cast<cellZoneMesh&>(mesh_.cellZones()).movePoints(points);
    mesh_.clearCellTree();

    meshObject::movePoints<polyMesh>(mesh_);
    meshObject::movePoints<pointMesh>(mesh_);

    if (deferFunctionObjects_)
    {
        functionObjectsPending_ = true;
    }
    else
    {
        const_cast<Time&>(mesh_.time()).functionObjects().movePoints(mesh_);
    }

    // As fvMesh::movePoints after the mesh flux
    const_cast<fvBoundaryMesh&>(mesh_.boundary()).movePoints();
    meshObject::movePoints<fvMesh>(mesh_);
    meshObject::movePoints<lduMesh>(mesh_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bandMeshMotion::bandMeshMotion
(
    fvMesh& mesh,
    const labelUList& movingPoints
)
:
    mesh_(mesh),
    whole_(false),
    deferFunctionObjects_(false),
    functionObjectsPending_(false),
    timeIndex_(-1),
    oldCentresIndex_(-1),
    centresEvent_(-1),
    movedInStep_(mesh.nPoints()),
    changedPoints_(mesh.nPoints()),
    changedCells_(mesh.nCells()),
    nUpdates_(0),
    nUnchangedUpdates_(0),
    nFaceUpdates_(0)
{
    bitSet inBand(mesh.nPoints());
    inBand.set(movingPoints);
    points_ = inBand.toc();

    const labelListList& pointFaces = mesh.pointFaces();
    bitSet bandFaces(mesh.nFaces());
    for (const label pointi : points_)
    {
        bandFaces.set(pointFaces[pointi]);
    }
    faces_ = bandFaces.toc();
    facePatch_ = patchOf(mesh, faces_);

    const labelList& own = mesh.faceOwner();
    const labelList& nei = mesh.faceNeighbour();
    bitSet bandCells(mesh.nCells());
    for (const label facei : faces_)
    {
        bandCells.set(own[facei]);
        if (facei < mesh.nInternalFaces())
        {
            bandCells.set(nei[facei]);
        }
    }
    cells_ = bandCells.toc();

    const cellList& cells = mesh.cells();
    bitSet cellsFaces(mesh.nFaces());
    cellFaces_.setSize(cells_.size());
    forAll(cells_, i)
    {
        const label celli = cells_[i];
        labelList owned, neighboured;
        for (const label facei : cells[celli])
        {
            (own[facei] == celli ? owned : neighboured).append(facei);
        }
        sort(owned);
        sort(neighboured);
        cellFaces_[i] = owned;
        cellFaces_[i].append(neighboured);
        cellsFaces.set(cells[celli]);
    }
    interpFaces_ = cellsFaces.toc();
    interpFacePatch_ = patchOf(mesh, interpFaces_);
    for (label& patchi : interpFacePatch_)
    {
        if (patchi >= 0 && mesh.boundaryMesh()[patchi].coupled())
        {
            // updateProcessorFactors (or the whole update) sets these
            patchi = -1;
        }
    }

    // Processor patches: their interpolation factors use the other side's
    // cell centres, which the band of either side may move, so all of
    // them are updated after each exchange (updateProcessorFactors; a few
    // thousand faces). Other coupled patches (cyclic, AMI: transforms and
    // weights of their own) touching the band's cells take the whole
    // update.
    const polyBoundaryMesh& pbm = mesh.boundaryMesh();
    forAll(pbm, patchi)
    {
        if (isA<processorPolyPatch>(pbm[patchi]))
        {
            processorPatches_.append(patchi);
        }
    }
    for (const label facei : interpFaces_)
    {
        if (facei >= mesh.nInternalFaces())
        {
            const label patchi = pbm.whichPatch(facei);
            if
            (
                pbm[patchi].coupled()
             && !isA<processorPolyPatch>(pbm[patchi])
            )
            {
                whole_ = true;
            }
        }
    }
    reduce(whole_, orOp<bool>());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bandMeshMotion::movePoints(const pointField& newPoints)
{
    const label timeIndex = mesh_.time().timeIndex();

    // The first motion: OpenFOAM creates meshPhi, V0 and the old points
    if
    (
        whole_
     || timeIndex_ == -1
     || !mesh_.moving()
     || &mesh_.oldPoints() == &mesh_.points()
    )
    {
        mesh_.movePoints(newPoints);
        timeIndex_ = timeIndex;
        return;
    }

    if (timeIndex != timeIndex_)
    {
        storeOldGeometry();
        timeIndex_ = timeIndex;
    }
    updateGeometry(newPoints);
    notify();
}


Foam::label Foam::bandMeshMotion::nCellsWithin(const label nLayers) const
{
    bitSet within(mesh_.nCells());
    within.set(cells_);
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    for (label layer = 0; layer < nLayers; ++layer)
    {
        // One layer: the cells across an internal face from the set
        bitSet next(within);
        forAll(nei, facei)
        {
            const label o = own[facei];
            const label n = nei[facei];
            if (within.test(o) != within.test(n))
            {
                next.set(within.test(o) ? n : o);
            }
        }
        within.transfer(next);
    }
    return label(within.count());
}


void Foam::bandMeshMotion::notifyFunctionObjects()
{
    if (functionObjectsPending_)
    {
        const_cast<Time&>(mesh_.time()).functionObjects().movePoints(mesh_);
        functionObjectsPending_ = false;
    }
}


// ************************************************************************* //
