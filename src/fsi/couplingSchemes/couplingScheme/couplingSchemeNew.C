#include "couplingScheme.H"
#include "error.H"
#include "keywordCheck.H"

Foam::autoPtr<Foam::couplingScheme> Foam::couplingScheme::New
(
    const dictionary& dict
)
{
    // One coupling{} for every scheme, so that a case switches the scheme
    // by its name alone: the entries of each scheme are valid for all
    foamTools::checkKeywords
    (
        dict,
        {
            "scheme", "maxIter", "tolerance", "velocityScale",
            "onNonConvergence",
            "solidSubcycles",       // fluidSolidInteraction
            "initialRelaxation",    // aitken, IQNILS
            "reuse"                 // IQNILS
        }
    );
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
