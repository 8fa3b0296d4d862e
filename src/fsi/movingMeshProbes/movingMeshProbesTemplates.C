#include "movingMeshProbes.H"
#include "volFields.H"
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


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
void Foam::movingMeshProbes::sampleAndWriteFit(const fieldGroup<Type>& fields)
{
    typedef GeometricField<Type, fvPatchField, volMesh> fieldType;

    for (const word& fieldName : fields)
    {
        autoPtr<fieldType> fromFile;
        if (loadFromFiles_)
        {
            fromFile.reset
            (
                new fieldType
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
        }
        else if (!mesh_.foundObject<fieldType>(fieldName))
        {
            continue;
        }
        const fieldType& vField =
            fromFile.valid()
          ? fromFile() : mesh_.lookupObject<fieldType>(fieldName);

        const Field<Type> values(sampleFit(vField));

        // probes' rows: the time, then each probe's value
        if (Pstream::master())
        {
            const unsigned int w = IOstream::defaultPrecision() + 7;
            OFstream& os = *probeFilePtrs_[vField.name()];
            os  << setw(w) << vField.time().timeOutputValue();
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
}


// ************************************************************************* //
