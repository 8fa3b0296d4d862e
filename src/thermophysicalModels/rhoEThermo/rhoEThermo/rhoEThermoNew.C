#include "rhoEThermo.H"
#include "Time.H"
#include "keywordCheck.H"

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

    // The coefficients of every law may stay in the file (a case switches
    // the law by its name); those of the selected one: rhoEThermoModel.
    // thermoType and mixture: OpenFOAM's own thermo, for a case that a
    // stock solver runs too (the rhoCentralFoam peer of the shock tubes,
    // tests/verification/rhoCentralFoamSod); not read here
    wordList valid{"equationOfState", "thermoType", "mixture"};
    for (const word& law : meshConstructorTablePtr_->sortedToc())
    {
        valid.append(law + "Coeffs");
    }
    foamTools::checkKeywords(dict, valid);

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
