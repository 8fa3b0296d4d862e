#include "movingMeshProbes.H"
#include "localCellPoint.H"
#include "scaleFreeCellPointWeight.H"
#include "interpolationCellPoint.H"
#include <cstring>
#include "volFields.H"
#include "surfaceFields.H"
#include "IOmanip.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{

//- Combine the ranks' values of a probe: the one that found it (the
//  others hold probes' unset value)
template<class T>
class movingMeshProbesFoundOp
{
public:

    void operator()(T& x, const T& y) const
    {
        if (x == T(-VGREAT*pTraits<T>::one))
        {
            x = y;
        }
    }
};

} // End namespace Foam


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::movingMeshProbes::sampleFit
(
    const GeometricField<Type, fvPatchField, volMesh>& vField
) const
{
    List<labelList> cells;
    List<scalarList> weights;
    fitWeights(cells, weights);

    const Type unset(-VGREAT*pTraits<Type>::one);
    tmp<Field<Type>> tvalues(new Field<Type>(size(), unset));
    Field<Type>& values = tvalues.ref();
    forAll(*this, probei)
    {
        if (cells[probei].size())
        {
            Type v(Zero);
            forAll(cells[probei], i)
            {
                v += weights[probei][i]*vField[cells[probei][i]];
            }
            values[probei] = v;
        }
    }
    Pstream::listCombineGather(values, movingMeshProbesFoundOp<Type>());
    Pstream::listCombineScatter(values);
    return tvalues;
}


template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::movingMeshProbes::wholeFieldCellPoint
(
    const GeometricField<Type, fvPatchField, volMesh>& vField,
    const PtrList<scaleFreeCellPointWeight>& tets
) const
{
    // interpolationCellPoint over the whole field (all ranks:
    // volPointInterpolation synchronises) in the probes' tetrahedra
    tmp<Field<Type>> tvalues
    (
        new Field<Type>(size(), -VGREAT*pTraits<Type>::one)
    );
    Field<Type>& values = tvalues.ref();
    const interpolationCellPoint<Type> whole(vField);
    forAll(*this, probei)
    {
        if (tets.set(probei))
        {
            values[probei] =
                whole.interpolate(tets[probei].weights(), tets[probei].tet());
        }
    }
    Pstream::listCombineGather(values, movingMeshProbesFoundOp<Type>());
    Pstream::listCombineScatter(values);
    return tvalues;
}


template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::movingMeshProbes::sampleCellPoint
(
    const GeometricField<Type, fvPatchField, volMesh>& vField
) const
{
    // The tetrahedral decomposition's base points: built on every rank
    // (findFaceBasePts synchronises coupled faces), as interpolationCellPoint
    // builds them
    (void)mesh_.tetBasePtIs();

    const localCellPoint interpolator(mesh_);
    PtrList<scaleFreeCellPointWeight> tets(size());
    bool local = true;
    bool coupled = false;
    forAll(*this, probei)
    {
        const label celli = elementList_[probei];
        if (celli >= 0)
        {
            tets.set
            (
                probei,
                new scaleFreeCellPointWeight(mesh_, operator[](probei), celli)
            );
            local = local && interpolator.exact<Type>(tets[probei]);
            coupled = coupled || interpolator.coupled(tets[probei]);
        }
    }

    const Type unset(-VGREAT*pTraits<Type>::one);
    tmp<Field<Type>> tvalues(new Field<Type>(size(), unset));
    Field<Type>& values = tvalues.ref();

    // The whole-field interpolation if a probe needs it
    if (!returnReduce(local, andOp<bool>()))
    {
        return wholeFieldCellPoint(vField, tets);
    }

    // The values at the processor patches' points (all ranks) if a
    // probe's tetrahedron has one
    tmp<Field<Type>> tatCoupled(new Field<Type>());
    coupled = returnReduce(coupled, orOp<bool>());
    if (coupled)
    {
        tatCoupled = interpolator.coupledValues(vField);
    }

    forAll(*this, probei)
    {
        if (tets.set(probei))
        {
            values[probei] =
                interpolator.interpolate(vField, tets[probei], tatCoupled());
        }
    }
    Pstream::listCombineGather(values, movingMeshProbesFoundOp<Type>());
    Pstream::listCombineScatter(values);

    // Debug: the whole-field interpolation's values in the same
    // tetrahedra, which these must equal to the last bit
    if (debug)
    {
        const Field<Type> whole(wholeFieldCellPoint(vField, tets));
        forAll(values, probei)
        {
            if
            (
                processor_[probei] != -1
             && std::memcmp(&values[probei], &whole[probei], sizeof(Type))
            )
            {
                FatalErrorInFunction
                    << "field " << vField.name() << ", probe " << probei
                    << " at " << operator[](probei) << ": localCellPoint "
                    << values[probei] << ", the whole-field interpolation "
                    << whole[probei] << " (not the same bits)"
                    << exit(FatalError);
            }
        }
        Info<< type() << ' ' << name() << ": field " << vField.name()
            << ": localCellPoint (processor points: "
            << (coupled ? "yes" : "no") << "), the same bits as the"
            << " whole-field interpolation" << endl;
    }
    return tvalues;
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class GeoField>
const GeoField* Foam::movingMeshProbes::field
(
    const word& fieldName,
    autoPtr<GeoField>& fromFile
) const
{
    if (loadFromFiles_)
    {
        fromFile.reset
        (
            new GeoField
            (
                IOobject
                (
                    fieldName,
                    mesh_.time().timeName(),
                    mesh_,
                    IOobject::MUST_READ,
                    IOobject::NO_WRITE,
                    false
                ),
                mesh_
            )
        );
        return fromFile.get();
    }
    return mesh_.findObject<GeoField>(fieldName);
}


template<class Type>
void Foam::movingMeshProbes::writeRow
(
    const word& fieldName,
    const Field<Type>& values
)
{
    // probes' rows: the time, then each probe's value
    if (Pstream::master())
    {
        const unsigned int w = IOstream::defaultPrecision() + 7;
        OFstream& os = *probeFilePtrs_[fieldName];
        os  << setw(w) << mesh_.time().timeOutputValue();
        forAll(values, probei)
        {
            if (includeOutOfBounds_ || processor_[probei] != -1)
            {
                os  << ' ' << setw(w) << values[probei];
            }
        }
        os  << endl;
    }
}


template<class Type>
void Foam::movingMeshProbes::sampleAndWriteVol(const fieldGroup<Type>& fields)
{
    typedef GeometricField<Type, fvPatchField, volMesh> fieldType;

    for (const word& fieldName : fields)
    {
        autoPtr<fieldType> fromFile;
        const fieldType* vField = field(fieldName, fromFile);
        if (vField)
        {
            const Field<Type> values
            (
                linearFit() ? sampleFit(*vField) : sampleCellPoint(*vField)
            );
            writeRow(fieldName, values);
        }
    }
}


template<class Type>
void Foam::movingMeshProbes::sampleAndWriteSurface
(
    const fieldGroup<Type>& fields
)
{
    typedef GeometricField<Type, fvsPatchField, surfaceMesh> fieldType;

    for (const word& fieldName : fields)
    {
        autoPtr<fieldType> fromFile;
        const fieldType* sField = field(fieldName, fromFile);
        if (sField)
        {
            const Field<Type> values(sample(*sField));
            writeRow(fieldName, values);
        }
    }
}


// ************************************************************************* //
