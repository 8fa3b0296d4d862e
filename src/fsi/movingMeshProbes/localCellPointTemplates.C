#include "localCellPoint.H"
#include "volFields.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
Type Foam::localCellPoint::pointValue
(
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    const label pointi
) const
{
    const point& x = mesh_.points()[pointi];
    const label nInternalFaces = mesh_.nInternalFaces();
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const labelList& pFaces = mesh_.pointFaces()[pointi];

    // The point's faces that weight it (in volPointInterpolation's order:
    // the boundary patch's pointFaces, ascending as polyMesh's)
    DynamicList<label, 16> faces;
    for (const label facei : pFaces)
    {
        if (facei >= nInternalFaces && weighted_[pbm.whichPatch(facei)])
        {
            faces.append(facei);
        }
    }

    Type value(Zero);

    if (faces.empty())
    {
        // makeInternalWeights, makeWeights' normalisation,
        // interpolateInternalField
        const labelList& pCells = mesh_.pointCells()[pointi];
        const scalarList w
        (
            inverseDistanceWeights(x, mesh_.cellCentres(), pCells)
        );
        forAll(pCells, i)
        {
            value += w[i]*vf[pCells[i]];
        }
    }
    else
    {
        // makeBoundaryWeights, makeWeights' normalisation,
        // interpolateBoundaryField (flatBoundaryField: zero on a coupled
        // patch of the field)
        const scalarList w
        (
            inverseDistanceWeights(x, mesh_.faceCentres(), faces)
        );
        forAll(faces, j)
        {
            const label patchi = pbm.whichPatch(faces[j]);
            const fvPatchField<Type>& pf = vf.boundaryField()[patchi];
            const Type boundaryValue
            (
                pf.coupled()
              ? Type(Zero) : pf[faces[j] - pbm[patchi].start()]
            );
            value += w[j]*boundaryValue;
        }
    }

    return value;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
bool Foam::localCellPoint::exact(const cellPointWeight& cpw) const
{
    const bool isScalar = std::is_same<Type, scalar>::value;
    for (const label pointi : cpw.faceVertices())
    {
        if (!keeps(pointi, isScalar))
        {
            return false;
        }
    }
    return true;
}


template<class Type>
Type Foam::localCellPoint::interpolate
(
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    const cellPointWeight& cpw
) const
{
    // interpolationCellPoint::interpolate(const cellPointWeight&)
    const barycentric& weights = cpw.weights();
    const triFace& faceVertices = cpw.faceVertices();

    Type t = vf[cpw.cell()]*weights[0];
    t += pointValue(vf, faceVertices[0])*weights[1];
    t += pointValue(vf, faceVertices[1])*weights[2];
    t += pointValue(vf, faceVertices[2])*weights[3];

    return t;
}


// ************************************************************************* //
