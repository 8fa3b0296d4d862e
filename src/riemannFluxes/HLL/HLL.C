#include "HLL.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace riemannFluxes
{
    defineTypeNameAndDebug(HLL, 0);
    addToRunTimeSelectionTable(riemannFlux, HLL, mesh);
}
}


void Foam::riemannFluxes::HLL::solve
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

        const scalar SL = min(qL - cL, qR - cR);
        const scalar SR = max(qL + cL, qR + cR);

        scalar fmL, feL, fmR, feR;
        vector fuL, fuR;
        physicalFlux(rhoL, UL, pL, EL, qL, n, fmL, fuL, feL);
        physicalFlux(rhoR, UR, pR, ER, qR, n, fmR, fuR, feR);

        scalar fMass, fEnergy;
        vector fMom;
        if (SL >= 0)
        {
            fMass = fmL; fMom = fuL; fEnergy = feL;
        }
        else if (SR <= 0)
        {
            fMass = fmR; fMom = fuR; fEnergy = feR;
        }
        else
        {
            const scalar r = 1/(SR - SL);
            fMass = r*(SR*fmL - SL*fmR + SL*SR*(rhoR - rhoL));
            fMom = r*(SR*fuL - SL*fuR + SL*SR*(rhoR*UR - rhoL*UL));
            fEnergy = r*(SR*feL - SL*feR + SL*SR*(rhoR*ER - rhoL*EL));
        }

        F.mass[facei] = A*fMass;
        F.momentum[facei] = A*fMom;
        F.energy[facei] = A*fEnergy;
        F.amaxSf[facei] = A*max(mag(SL), mag(SR));
    }
}
