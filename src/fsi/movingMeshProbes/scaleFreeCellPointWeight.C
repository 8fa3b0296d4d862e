#include "scaleFreeCellPointWeight.H"
#include "polyMesh.H"
#include "polyMeshTetDecomposition.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::scaleFreeCellPointWeight::degenerate(1e-12);


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

bool Foam::scaleFreeCellPointWeight::barycentricCoordinates
(
    const tetPointRef& tet,
    const point& pt,
    barycentric& bary,
    scalar& det
)
{
    // tetrahedron::pointToBarycentric's operations, with a relative test
    const vector e0(tet.a() - tet.d());
    const vector e1(tet.b() - tet.d());
    const vector e2(tet.c() - tet.d());

    const tensor t
    (
        e0.x(), e1.x(), e2.x(),
        e0.y(), e1.y(), e2.y(),
        e0.z(), e1.z(), e2.z()
    );

    det = Foam::det(t);

    if (Foam::mag(det) <= degenerate*mag(e0)*mag(e1)*mag(e2))
    {
        bary = barycentric(0.25, 0.25, 0.25, 0.25);
        return false;
    }

    const vector res = inv(t, det) & (pt - tet.d());

    bary[0] = res.x();
    bary[1] = res.y();
    bary[2] = res.z();
    bary[3] = 1 - cmptSum(res);

    return true;
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::scaleFreeCellPointWeight::findTetrahedron
(
    const polyMesh& mesh,
    const vector& position,
    const label celli
)
{
    const List<tetIndices> cellTets =
        polyMeshTetDecomposition::cellTetIndices(mesh, celli);

    const scalar cellVolume = mesh.cellVolumes()[celli];

    // cellPointWeight's containment tolerance (normalised values)
    const scalar tol = cellPointWeight::tol;

    forAll(cellTets, teti)
    {
        const tetIndices& tetIs = cellTets[teti];

        scalar det;
        if
        (
            barycentricCoordinates(tetIs.tet(mesh), position, weights_, det)
         && mag(det/cellVolume) > tol
        )
        {
            const scalar& u = weights_[0];
            const scalar& v = weights_[1];
            const scalar& w = weights_[2];

            if
            (
                (u + tol > 0)
             && (v + tol > 0)
             && (w + tol > 0)
             && (u + v + w < 1 + tol)
            )
            {
                tet_ = tetIs;
                faceVertices_ = tetIs.faceTriIs(mesh);
                return;
            }
        }
    }

    // No tetrahedron holds the position: the nearest one
    scalar minNearDist = VGREAT;
    label nearestTeti = -1;
    forAll(cellTets, teti)
    {
        const scalar nearDist =
            cellTets[teti].tet(mesh).nearestPoint(position).distance();

        if (nearDist < minNearDist)
        {
            minNearDist = nearDist;
            nearestTeti = teti;
        }
    }

    const tetIndices& tetIs = cellTets[nearestTeti];
    scalar det;
    barycentricCoordinates(tetIs.tet(mesh), position, weights_, det);
    tet_ = tetIs;
    faceVertices_ = tetIs.faceTriIs(mesh);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::scaleFreeCellPointWeight::scaleFreeCellPointWeight
(
    const polyMesh& mesh,
    const vector& position,
    const label celli
)
:
    celli_(celli)
{
    findTetrahedron(mesh, position, celli);
}


// ************************************************************************* //
