#include "riemannFlux.H"
#include "keywordCheck.H"

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

    autoPtr<riemannFlux> flux(cstrIter()(mesh));
    flux->wedgeFaces_ = foamTools::readEnumOrDefault
    (
        wedgeFaceModelNames, dict, "wedgeFaces", wedgeFaceModel::mirror
    );
    if (flux->wedgeFaces_ != wedgeFaceModel::mirror)
    {
        Info<< "Wedge faces: " << wedgeFaceModelNames[flux->wedgeFaces_]
            << " (the cell's pressure, no Riemann problem)" << endl;
    }
    return flux;
}
