#include "riemannFlux.H"

Foam::autoPtr<Foam::riemannFlux> Foam::riemannFlux::New
(
    const fvMesh& mesh,
    const dictionary& dict
)
{
    const word name(dict.get<word>("riemannSolver"));

    Info<< "Selecting Riemann solver " << name << endl;

    auto cstrIter = meshConstructorTablePtr_->cfind(name);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "riemannSolver",
            name,
            *meshConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<riemannFlux>(cstrIter()(mesh));
}
