#include "localCellPoint.H"
#include "volFields.H"
#include "pointConstraints.H"
#include "globalMeshData.H"
#include "mapDistribute.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
Type Foam::localCellPoint::weightedSum
(
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    const label pointi,
    const labelUList& faces,
    const scalarList& w,
    const scalar W
) const
{
    // makeWeights' normalisation (pw[i] /= sumWeights), then
    // interpolateInternalField or interpolateBoundaryField
    // (flatBoundaryField: zero on a coupled patch of the field)
    Type value(Zero);
    if (faces.empty())
    {
        const labelList& pCells = mesh_.pointCells()[pointi];
        forAll(pCells, i)
        {
            const scalar wi = w[i]/W;
            value += wi*vf[pCells[i]];
        }
    }
    else
    {
        const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
        forAll(faces, j)
        {
            const label patchi = pbm.whichPatch(faces[j]);
            const fvPatchField<Type>& pf = vf.boundaryField()[patchi];
            const Type boundaryValue
            (
                pf.coupled()
              ? Type(Zero) : pf[faces[j] - pbm[patchi].start()]
            );
            const scalar wj = w[j]/W;
            value += wj*boundaryValue;
        }
    }
    return value;
}


template<class Type>
Type Foam::localCellPoint::pointValue
(
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    const label pointi
) const
{
    const DynamicList<label, 16> faces(weightingFaces(pointi));
    scalar W = 0;
    const scalarList w(inverseDistances(pointi, faces, W));
    return weightedSum(vf, pointi, faces, w, W);
}


template<class Type>
void Foam::localCellPoint::pushUntransformed(List<Type>& pointData) const
{
    // volPointInterpolation::pushUntransformedData
    const globalMeshData& gmd = mesh_.globalData();
    const labelList& meshPoints = gmd.coupledPatch().meshPoints();
    const mapDistribute& slavesMap = gmd.globalCoPointSlavesMap();
    const labelListList& slaves = gmd.globalCoPointSlaves();

    List<Type> elems(slavesMap.constructSize());
    forAll(meshPoints, i)
    {
        elems[i] = pointData[meshPoints[i]];
    }
    forAll(slaves, i)
    {
        for (const label slavei : slaves[i])
        {
            elems[slavei] = elems[i];
        }
    }
    slavesMap.reverseDistribute(elems.size(), elems, false);
    forAll(meshPoints, i)
    {
        pointData[meshPoints[i]] = elems[i];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
bool Foam::localCellPoint::exact(const scaleFreeCellPointWeight& cpw) const
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
Foam::tmp<Foam::Field<Type>> Foam::localCellPoint::coupledValues
(
    const GeometricField<Type, fvPatchField, volMesh>& vf
) const
{
    // makeWeights and interpolate{Internal,Boundary}Field at the points
    // of the processor patches: the sums of the weights over the ranks
    // (syncUntransformedData, pushUntransformedData), the weighted values
    // with them, their sum over the ranks (the same two)
    const label nPoints = mesh_.nPoints();
    const labelList& meshPoints = mesh_.globalData().coupledPatch().meshPoints();

    List<DynamicList<label, 16>> faces(meshPoints.size());
    List<scalarList> w(meshPoints.size());
    boolList processor(meshPoints.size(), false);
    scalarField sumW(nPoints, Zero);
    forAll(meshPoints, i)
    {
        const label pointi = meshPoints[i];
        processor[i] = onProcessorPatch(pointi);
        if (processor[i])
        {
            faces[i] = weightingFaces(pointi);
            w[i] = inverseDistances(pointi, faces[i], sumW[pointi]);
        }
    }
    pointConstraints::syncUntransformedData
    (
        mesh_, sumW, plusEqOp<scalar>()
    );
    pushUntransformed(sumW);

    tmp<Field<Type>> tvalues(new Field<Type>(nPoints, Zero));
    Field<Type>& values = tvalues.ref();
    forAll(meshPoints, i)
    {
        const label pointi = meshPoints[i];
        if (processor[i])
        {
            values[pointi] =
                weightedSum(vf, pointi, faces[i], w[i], sumW[pointi]);
        }
    }
    pointConstraints::syncUntransformedData
    (
        mesh_, values, plusEqOp<Type>()
    );
    pushUntransformed(values);

    return tvalues;
}


template<class Type>
Type Foam::localCellPoint::interpolate
(
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    const scaleFreeCellPointWeight& cpw,
    const UList<Type>& atCoupled
) const
{
    // interpolationCellPoint::interpolate(const cellPointWeight&)
    const barycentric& weights = cpw.weights();
    const triFace& faceVertices = cpw.faceVertices();

    const auto value = [&](const label pointi)
    {
        if (onProcessorPatch(pointi))
        {
            if (atCoupled.size() != mesh_.nPoints())
            {
                FatalErrorInFunction
                    << "point " << pointi << " is on a processor patch:"
                    << " its value needs coupledValues()"
                    << abort(FatalError);
            }
            return atCoupled[pointi];
        }
        return pointValue(vf, pointi);
    };

    Type t = vf[cpw.cell()]*weights[0];
    t += value(faceVertices[0])*weights[1];
    t += value(faceVertices[1])*weights[2];
    t += value(faceVertices[2])*weights[3];

    return t;
}


// ************************************************************************* //
