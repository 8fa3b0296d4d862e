#include "rungeKuttaScheme.H"
#include "keywordCheck.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::rungeKuttaScheme::type>
Foam::rungeKuttaScheme::names
{
    { type::Euler, "Euler" },
    { type::SSPRK2, "SSPRK2" },
    { type::SSPRK3, "SSPRK3" },
};


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rungeKuttaScheme::rungeKuttaScheme(const dictionary& dict)
{
    const type t =
        foamTools::readEnumOrDefault(names, dict, "timeScheme", type::SSPRK3);
    switch (t)
    {
        case type::Euler: a_ = {0}; break;
        case type::SSPRK2: a_ = {0, 0.5}; break;
        case type::SSPRK3: a_ = {0, 0.75, 1.0/3.0}; break;
    }
    Info<< "Time scheme " << names[t] << " (" << a_.size() << " stages)"
        << nl << endl;
}


// ************************************************************************* //
