#include "localCellPoint.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "symmetryPlanePolyPatch.H"
#include "symmetryPolyPatch.H"
#include "processorPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "surfaceFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::localCellPoint::localCellPoint(const fvMesh& mesh)
:
    mesh_(mesh),
    weighted_(mesh.boundaryMesh().size(), false),
    keepsScalar_(mesh.boundaryMesh().size(), false),
    keepsAny_(mesh.boundaryMesh().size(), false),
    processor_(mesh.boundaryMesh().size(), false)
{
    const polyBoundaryMesh& pbm = mesh.boundaryMesh();
    const surfaceScalarField::Boundary& magSfbf = mesh.magSf().boundaryField();

    forAll(pbm, patchi)
    {
        const polyPatch& pp = pbm[patchi];

        // volPointInterpolation::calcBoundaryAddressing's test is
        // magSf's; a patch coupled by any account is not kept (below), so
        // that weighted_ matters on uncoupled patches only
        const bool coupled =
            pp.coupled() || mesh.boundary()[patchi].coupled()
         || magSfbf[patchi].coupled();
        weighted_[patchi] = !isA<emptyPolyPatch>(pp) && !coupled;

        // A processor patch's points: summed over the ranks without a
        // transformation (coupledValues); processorCyclic transforms
        processor_[patchi] =
            isA<processorPolyPatch>(pp) && !isA<processorCyclicPolyPatch>(pp);

        // The point patch field of a constraint patch is of the patch's
        // type (pointPatchField::New); empty's evaluate does nothing (and
        // adds no corner constraint), wedge's, symmetryPlane's and
        // symmetry's transform the value (I - n n, or the mean with its
        // mirror image), which leaves a scalar as it is, as do the corner
        // constraints (pointConstraints::constrainCorners<scalar>)
        const word& type = pp.type();
        keepsAny_[patchi] =
            !coupled
         && (
                !polyPatch::constraintType(type)
             || type == emptyPolyPatch::typeName
            );
        keepsScalar_[patchi] =
            keepsAny_[patchi]
         || (
                !coupled
             && (
                    type == wedgePolyPatch::typeName
                 || type == symmetryPlanePolyPatch::typeName
                 || type == symmetryPolyPatch::typeName
                )
            );
    }
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::localCellPoint::onProcessorPatch(const label pointi) const
{
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    for (const label facei : mesh_.pointFaces()[pointi])
    {
        const label patchi = pbm.whichPatch(facei);
        if (patchi != -1 && processor_[patchi])
        {
            return true;
        }
    }
    return false;
}


Foam::DynamicList<Foam::label, 16> Foam::localCellPoint::weightingFaces
(
    const label pointi
) const
{
    // volPointInterpolation's boundary patch's pointFaces: ascending as
    // polyMesh's pointFaces
    const label nInternalFaces = mesh_.nInternalFaces();
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    DynamicList<label, 16> faces;
    for (const label facei : mesh_.pointFaces()[pointi])
    {
        if (facei >= nInternalFaces && weighted_[pbm.whichPatch(facei)])
        {
            faces.append(facei);
        }
    }
    return faces;
}


Foam::scalarList Foam::localCellPoint::inverseDistances
(
    const label pointi,
    const labelUList& faces,
    scalar& sum
) const
{
    // makeInternalWeights / makeBoundaryWeights: the weights and their
    // running sum from zero, in the same order
    const point& x = mesh_.points()[pointi];
    const bool boundary = faces.size();
    const labelUList& labels =
        boundary ? faces : labelUList(mesh_.pointCells()[pointi]);
    const vectorField& centres =
        boundary ? mesh_.faceCentres() : mesh_.cellCentres();

    scalarList w(labels.size());
    sum = 0;
    forAll(labels, i)
    {
        w[i] = 1.0/mag(x - centres[labels[i]]);
        sum += w[i];
    }
    return w;
}


bool Foam::localCellPoint::keeps
(
    const label pointi,
    const bool isScalar
) const
{
    // A point on a coupled patch's face is one of globalMeshData's coupled
    // points, whose values volPointInterpolation synchronises: kept on a
    // processor patch (coupledValues sums them as it does), not on a
    // transforming one
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const boolList& keeps = isScalar ? keepsScalar_ : keepsAny_;
    for (const label facei : mesh_.pointFaces()[pointi])
    {
        const label patchi = pbm.whichPatch(facei);
        if (patchi != -1 && !keeps[patchi] && !processor_[patchi])
        {
            return false;
        }
    }
    return true;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::localCellPoint::coupled(const scaleFreeCellPointWeight& cpw) const
{
    for (const label pointi : cpw.faceVertices())
    {
        if (onProcessorPatch(pointi))
        {
            return true;
        }
    }
    return false;
}


// ************************************************************************* //
