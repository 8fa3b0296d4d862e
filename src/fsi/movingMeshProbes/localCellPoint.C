#include "localCellPoint.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "symmetryPlanePolyPatch.H"
#include "symmetryPolyPatch.H"
#include "surfaceFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::localCellPoint::localCellPoint(const fvMesh& mesh)
:
    mesh_(mesh),
    weighted_(mesh.boundaryMesh().size(), false),
    keepsScalar_(mesh.boundaryMesh().size(), false),
    keepsAny_(mesh.boundaryMesh().size(), false)
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

Foam::scalarList Foam::localCellPoint::inverseDistanceWeights
(
    const point& x,
    const vectorField& centres,
    const labelUList& labels
)
{
    scalarList w(labels.size());
    scalar sumW = 0;
    forAll(labels, i)
    {
        w[i] = 1.0/mag(x - centres[labels[i]]);
        sumW += w[i];
    }
    forAll(labels, i)
    {
        w[i] /= sumW;
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
    // points, whose values volPointInterpolation synchronises: not kept
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const boolList& keeps = isScalar ? keepsScalar_ : keepsAny_;
    for (const label facei : mesh_.pointFaces()[pointi])
    {
        const label patchi = pbm.whichPatch(facei);
        if (patchi != -1 && !keeps[patchi])
        {
            return false;
        }
    }
    return true;
}


// ************************************************************************* //
