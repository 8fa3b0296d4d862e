#include "robin.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(robin, 0);
    addToRunTimeSelectionTable(couplingScheme, robin, dictionary);
}


Foam::robin::robin(const dictionary& dict)
:
    couplingScheme(dict)
{}


void Foam::robin::relax
(
    scalarField& x,
    const scalarField&,
    const scalarField& r,
    const scalarField& beta
)
{
    x += r/(1 + beta);
}
