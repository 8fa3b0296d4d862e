#include "globalInterfacePatch.H"
#include "Pstream.H"

template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::globalInterfacePatch::faceValues
(
    const UList<Type>& local
) const
{
    if (!Pstream::parRun())
    {
        return tmp<Field<Type>>(new Field<Type>(local));
    }
    tmp<Field<Type>> tall(new Field<Type>());
    faceOffsets_.gather(local, tall.ref());
    Pstream::scatter(tall.ref());
    return tall;
}


template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::globalInterfacePatch::localPointValues
(
    const UList<Type>& global
) const
{
    return tmp<Field<Type>>
    (
        new Field<Type>(UIndirectList<Type>(global, localToGlobal_))
    );
}
