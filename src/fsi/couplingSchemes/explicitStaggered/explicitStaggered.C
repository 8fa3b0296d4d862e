#include "explicitStaggered.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(explicitStaggered, 0);
    addToRunTimeSelectionTable(couplingScheme, explicitStaggered, dictionary);
}


Foam::explicitStaggered::explicitStaggered(const dictionary& dict)
:
    couplingScheme(dict)
{}


void Foam::explicitStaggered::relax
(
    scalarField&,
    const scalarField&,
    const scalarField&,
    const scalarField&
)
{
    // Never called: the scheme is not iterative
    FatalErrorInFunction
        << "explicitStaggered does not iterate" << abort(FatalError);
}
