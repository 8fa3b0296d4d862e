#include "couplingScheme.H"
#include "fsiRanges.H"
#include "error.H"
#include "keywordCheck.H"
#include "inputChecks.H"

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
            "onNonConvergence", "predictor",
            "solidSubcycles",       // fluidSolidInteraction
            "initialRelaxation",    // aitken, IQNILS
            "reuse"                 // IQNILS
        }
    );
    // ... and valid whichever scheme runs: an entry of another scheme is
    // checked too (was: an out-of-range reuse under aitken passed silently
    // until the scheme was switched; issue 19)
    if (dict.found("initialRelaxation"))
    {
        fsiRanges::read<scalar>(dict, "coupling", "initialRelaxation");
    }
    if (dict.found("reuse"))
    {
        fsiRanges::read<label>(dict, "coupling", "reuse");
    }
    // One of the schemes' names, named with the file, the line and the
    // closest name (adv48b g39: OpenFOAM's "Unknown coupling scheme type
    // Robin", neither)
    const word name
    (
        foamTools::readOneOf
        (
            dict, "scheme", dictionaryConstructorTablePtr_->sortedToc()
        )
    );

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
    autoPtr<couplingScheme> scheme(cstrIter()(dict));
    if (!scheme->iterative() && scheme->extrapolated())
    {
        FatalIOErrorInFunction(dict)
            << "predictor extrapolated needs an iterative scheme (aitken,"
            << " IQNILS, robin): " << name << " takes one pass with the"
            << " centralDifference predictor v_n + dt/2 a_n, which keeps"
            << " the fluid wall on the solid's displacement"
            << exit(FatalIOError);
    }
    return scheme;
}
