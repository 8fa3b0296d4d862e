#include "rusanov.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace riemannFluxes
{
    defineTypeNameAndDebug(rusanov, 0);
    addToRunTimeSelectionTable(riemannFlux, rusanov, mesh);
}
}


void Foam::riemannFluxes::rusanov::solve
(
    const faceStates& L,
    const faceStates& R,
    const vectorField& Sf,
    const scalarField& magSf,
    faceFluxes& F
) const
{
    forAll(Sf, facei)
    {
        const scalar A = magSf[facei];
        const vector n = Sf[facei]/A;

        const scalar rhoL = L.rho[facei], rhoR = R.rho[facei];
        const vector& UL = L.U[facei];
        const vector& UR = R.U[facei];
        const scalar pL = L.p[facei], pR = R.p[facei];
        const scalar cL = L.c[facei], cR = R.c[facei];
        const scalar EL = L.e[facei] + 0.5*magSqr(UL);
        const scalar ER = R.e[facei] + 0.5*magSqr(UR);
        const scalar qL = UL & n, qR = UR & n;

        const scalar S = max(mag(qL) + cL, mag(qR) + cR);

        scalar fmL, feL, fmR, feR;
        vector fuL, fuR;
        physicalFlux(rhoL, UL, pL, EL, qL, n, fmL, fuL, feL);
        physicalFlux(rhoR, UR, pR, ER, qR, n, fmR, fuR, feR);

        F.mass[facei] = A*(0.5*(fmL + fmR) - 0.5*S*(rhoR - rhoL));
        F.momentum[facei] = A*(0.5*(fuL + fuR) - 0.5*S*(rhoR*UR - rhoL*UL));
        F.energy[facei] = A*(0.5*(feL + feR) - 0.5*S*(rhoR*ER - rhoL*EL));
        F.amaxSf[facei] = A*S;
    }
}
