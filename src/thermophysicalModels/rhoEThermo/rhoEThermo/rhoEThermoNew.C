#include "rhoEThermo.H"
#include "Time.H"

Foam::autoPtr<Foam::rhoEThermo> Foam::rhoEThermo::New(const fvMesh& mesh)
{
    const IOdictionary dict
    (
        IOobject
        (
            "thermophysicalProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );

    const word lawName(dict.get<word>("equationOfState"));

    Info<< "Selecting equation of state " << lawName << endl;

    auto cstrIter = meshConstructorTablePtr_->cfind(lawName);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "equationOfState",
            lawName,
            *meshConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<rhoEThermo>(cstrIter()(mesh));
}
