#include "riemannFlux.H"
#include "wallFvPatch.H"
#include "symmetryPlaneFvPatch.H"
#include "symmetryFvPatch.H"
#include "wedgeFvPatch.H"

namespace Foam
{
    defineTypeNameAndDebug(riemannFlux, 0);
    defineRunTimeSelectionTable(riemannFlux, mesh);
}


namespace
{

//- Patches whose outer state is the mirror image of the inner one
bool reflecting(const Foam::fvPatch& patch)
{
    using namespace Foam;
    return
        isA<wallFvPatch>(patch)
     || isA<symmetryPlaneFvPatch>(patch)
     || isA<symmetryFvPatch>(patch)
     || isA<wedgeFvPatch>(patch);
}

} // End anonymous namespace


void Foam::riemannFlux::faceStates::complete(const rhoEThermo& thermo)
{
    e.setSize(rho.size());
    c.setSize(rho.size());
    thermo.eFromRhoP(rho, p, e);
    thermo.cFromRhoE(rho, e, c);
}


Foam::riemannFlux::riemannFlux(const fvMesh& mesh)
:
    mesh_(mesh),
    reconstruction_(mesh)
{}


void Foam::riemannFlux::solveMoving
(
    faceStates& L,
    faceStates& R,
    const vectorField& Sf,
    const scalarField& magSf,
    const scalarField* wPtr,
    faceFluxes& F
) const
{
    if (!wPtr)
    {
        solve(L, R, Sf, magSf, F);
        return;
    }

    // Riemann problem in the frame of the moving face, then back:
    // F_mom = F'_mom + w n F_mass,
    // F_E   = F'_E + w n.F'_mom + w^2/2 F_mass
    const scalarField& w = *wPtr;
    const vectorField n(Sf/magSf);
    L.U -= w*n;
    R.U -= w*n;
    solve(L, R, Sf, magSf, F);
    forAll(w, facei)
    {
        const scalar wi = w[facei];
        F.energy[facei] +=
            wi*(n[facei] & F.momentum[facei]) + 0.5*wi*wi*F.mass[facei];
        F.momentum[facei] += wi*F.mass[facei]*n[facei];
    }
}


void Foam::riemannFlux::fluxes
(
    const rhoEThermo& thermo,
    const volVectorField& U,
    surfaceScalarField& massFlux,
    surfaceVectorField& momentumFlux,
    surfaceScalarField& energyFlux,
    surfaceScalarField& amaxSf
) const
{
    const volScalarField& rho = thermo.rho();
    const volScalarField& p = thermo.p();


    // Normal speed of moving faces [m/s]
    tmp<surfaceScalarField> tw;
    if (mesh_.moving())
    {
        tw = mesh_.phi()/mesh_.magSf();
    }

    // Internal faces
    {
        reconstruction_.reconstruct(rho, U, p, L_, R_);
        L_.complete(thermo);
        R_.complete(thermo);

        faceFluxes F
        {
            massFlux.primitiveFieldRef(),
            momentumFlux.primitiveFieldRef(),
            energyFlux.primitiveFieldRef(),
            amaxSf.primitiveFieldRef()
        };
        solveMoving
        (
            L_, R_, mesh_.Sf(), mesh_.magSf(),
            tw.valid() ? &tw().primitiveField() : nullptr,
            F
        );
    }

    // Boundary faces
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        if (patch.size() == 0)
        {
            continue;
        }

        faceStates Lp, Rp;
        if (patch.coupled())
        {
            reconstruction_.reconstructCoupled(patchi, rho, U, p, Lp, Rp);
        }
        else
        {
            Lp.rho = rho.boundaryField()[patchi].patchInternalField();
            Lp.U = U.boundaryField()[patchi].patchInternalField();
            Lp.p = p.boundaryField()[patchi].patchInternalField();

            if (reflecting(patch))
            {
                const vectorField n(patch.nf());
                scalarField qRel(Lp.U & n);
                if (tw.valid())
                {
                    qRel -= tw().boundaryField()[patchi];
                }
                Rp.rho = Lp.rho;
                Rp.U = Lp.U - 2*qRel*n;
                Rp.p = Lp.p;
            }
            else
            {
                Rp.rho = rho.boundaryField()[patchi];
                Rp.U = U.boundaryField()[patchi];
                Rp.p = p.boundaryField()[patchi];
            }
        }
        Lp.complete(thermo);
        Rp.complete(thermo);

        faceFluxes F
        {
            massFlux.boundaryFieldRef()[patchi],
            momentumFlux.boundaryFieldRef()[patchi],
            energyFlux.boundaryFieldRef()[patchi],
            amaxSf.boundaryFieldRef()[patchi]
        };
        solveMoving
        (
            Lp, Rp, patch.Sf(), patch.magSf(),
            tw.valid() ? &tw().boundaryField()[patchi] : nullptr,
            F
        );
    }
}
