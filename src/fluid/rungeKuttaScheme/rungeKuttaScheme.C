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
    // q(k) = a_k q(0) + (1 - a_k)(q(k-1) + dt L(q(k-1))): the time of the
    // combination, q(0) at fraction 0
    c_.setSize(a_.size());
    scalar previous = 0;
    forAll(a_, k)
    {
        c_[k] = (1 - a_[k])*(previous + 1);
        previous = c_[k];
    }
    // Every scheme here is consistent: its last state is at the step's
    // end, exactly (not 1 + 2^-53 by the products' rounding)
    c_.last() = 1;
    Info<< "Time scheme " << names[t] << " (" << a_.size() << " stages)"
        << nl << endl;
}


// ************************************************************************* //
