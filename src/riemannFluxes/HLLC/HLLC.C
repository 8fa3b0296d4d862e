#include "HLLC.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace riemannFluxes
{
    defineTypeNameAndDebug(HLLC, 0);
    addToRunTimeSelectionTable(riemannFlux, HLLC, mesh);
}
}


void Foam::riemannFluxes::HLLC::solve
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

        scalar fMass, fEnergy;
        vector fMom;
        if (SL >= 0)
        {
            physicalFlux(rhoL, UL, pL, EL, qL, n, fMass, fMom, fEnergy);
        }
        else if (SR <= 0)
        {
            physicalFlux(rhoR, UR, pR, ER, qR, n, fMass, fMom, fEnergy);
        }
        else
        {
            // Contact speed (Toro eq. 10.37)
            const scalar mL = rhoL*(SL - qL);
            const scalar mR = rhoR*(SR - qR);
            const scalar SStar = (pR - pL + mL*qL - mR*qR)/(mL - mR);

            // Star state of the side the face lies in (eq. 10.39),
            // flux F*K = FK + SK (U*K - UK) (eq. 10.38)
            const bool left = SStar >= 0;
            const scalar rhoK = left ? rhoL : rhoR;
            const vector& UK = left ? UL : UR;
            const scalar pK = left ? pL : pR;
            const scalar EK = left ? EL : ER;
            const scalar qK = left ? qL : qR;
            const scalar SK = left ? SL : SR;
            const scalar mK = left ? mL : mR;

            physicalFlux(rhoK, UK, pK, EK, qK, n, fMass, fMom, fEnergy);

            const scalar coef = mK/(SK - SStar);
            const scalar starMass = coef;
            const vector starMom = coef*(UK + (SStar - qK)*n);
            const scalar starEnergy =
                coef*(EK + (SStar - qK)*(SStar + pK/mK));

            fMass += SK*(starMass - rhoK);
            fMom += SK*(starMom - rhoK*UK);
            fEnergy += SK*(starEnergy - rhoK*EK);
        }

        F.mass[facei] = A*fMass;
        F.momentum[facei] = A*fMom;
        F.energy[facei] = A*fEnergy;
        F.amaxSf[facei] = A*max(mag(SL), mag(SR));
    }
}
