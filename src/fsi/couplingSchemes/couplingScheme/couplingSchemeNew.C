#include "couplingScheme.H"
#include "error.H"

Foam::autoPtr<Foam::couplingScheme> Foam::couplingScheme::New
(
    const dictionary& dict
)
{
    const word name(dict.get<word>("scheme"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(name);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "coupling scheme",
            name,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    Info<< "FSI coupling scheme " << name << endl;
    return autoPtr<couplingScheme>(cstrIter()(dict));
}
