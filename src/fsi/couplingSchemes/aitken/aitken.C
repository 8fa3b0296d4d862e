#include "aitken.H"
#include "fsiRanges.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"

namespace Foam
{
    defineTypeNameAndDebug(aitken, 0);
    addToRunTimeSelectionTable(couplingScheme, aitken, dictionary);
}


Foam::aitken::aitken(const dictionary& dict)
:
    couplingScheme(dict),
    omega0_
    (
        fsiRanges::readOrDefault<scalar>
        (
            dict, "coupling", "initialRelaxation", 0.1
        )
    ),
    omega_(omega0_)
{}


void Foam::aitken::newStep()
{
    omega_ = omega0_;
    rPrev_.clear();
}


void Foam::aitken::relax
(
    scalarField& x,
    const scalarField&,
    const scalarField& r,
    const scalarField&
)
{
    if (rPrev_.size() == r.size())
    {
        const scalarField dr(r - rPrev_);
        const scalar d2 = sumSqr(dr);
        if (d2 > 0)
        {
            omega_ = -omega_*sum(rPrev_*dr)/d2;
        }
    }
    x += omega_*r;
    rPrev_ = r;
}
