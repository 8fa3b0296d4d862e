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


const Foam::Enum<Foam::riemannFlux::wedgeFaceModel>
Foam::riemannFlux::wedgeFaceModelNames
({
    {wedgeFaceModel::mirror, "mirror"},
    {wedgeFaceModel::cellPressure, "cellPressure"},
});


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


//- The states of the cells next to the faces of patch (the left side of
//  its faces): patchInternalField's values, without its temporaries
void cellSideStates
(
    const Foam::fvPatch& patch,
    const Foam::scalarField& rho,
    const Foam::vectorField& U,
    const Foam::scalarField& p,
    Foam::MUSCLReconstruction::states& L
)
{
    const Foam::labelUList& faceCells = patch.faceCells();
    L.rho.setSize(faceCells.size());
    L.U.setSize(faceCells.size());
    L.p.setSize(faceCells.size());
    forAll(faceCells, facei)
    {
        const Foam::label celli = faceCells[facei];
        L.rho[facei] = rho[celli];
        L.U[facei] = U[celli];
        L.p[facei] = p[celli];
    }
}


//- The mirror image R of the states L on a reflecting patch: the normal
//  velocity relative to the face (speed w, if wPtr) reflected
//  (riemannFlux::mirrorVelocity, n = Sf/|Sf|)
void mirrorStates
(
    const Foam::fvPatch& patch,
    const Foam::scalarField* wPtr,
    const Foam::MUSCLReconstruction::states& L,
    Foam::MUSCLReconstruction::states& R
)
{
    using namespace Foam;
    const vectorField& Sf = patch.Sf();
    const scalarField& magSf = patch.magSf();
    R.rho = L.rho;
    R.p = L.p;
    R.U.setSize(L.U.size());
    forAll(Sf, facei)
    {
        const vector n = Sf[facei]/magSf[facei];
        R.U[facei] =
            riemannFlux::mirrorVelocity
            (
                L.U[facei], n, wPtr ? (*wPtr)[facei] : 0
            );
    }
}

} // End anonymous namespace


void Foam::riemannFlux::faceStates::complete(const rhoEThermo& thermo)
{
    e.setSize(rho.size());
    c.setSize(rho.size());
    thermo.ecFromRhoP(rho, p, e, c);
}


Foam::riemannFlux::riemannFlux(const fvMesh& mesh)
:
    mesh_(mesh),
    reconstruction_(mesh),
    wedgeFaces_(wedgeFaceModel::mirror)
{}


Foam::tmp<Foam::surfaceScalarField> Foam::riemannFlux::faceSpeeds() const
{
    if (mesh_.moving())
    {
        return mesh_.phi()/mesh_.magSf();
    }
    return tmp<surfaceScalarField>();
}


void Foam::riemannFlux::toFaceFrame
(
    faceStates& L,
    faceStates& R,
    const UList<vector>& Sf,
    const UList<scalar>& magSf,
    const UList<scalar>& w
)
{
    // The arithmetic of L.U -= w*n, R.U -= w*n with n = Sf/magSf, face by
    // face without the temporary fields (the same bits)
    forAll(Sf, facei)
    {
        const vector n = Sf[facei]/magSf[facei];
        const vector wn = w[facei]*n;
        L.U[facei] -= wn;
        R.U[facei] -= wn;
    }
}


void Foam::riemannFlux::patchStates
(
    const rhoEThermo& thermo,
    const volVectorField& U,
    const label patchi,
    const scalarField* wPtr,
    faceStates& L,
    faceStates& R,
    const bool firstOrder
) const
{
    const fvPatch& patch = mesh_.boundary()[patchi];
    const volScalarField& rho = thermo.rho();
    const volScalarField& p = thermo.p();

    if (patch.coupled() && !firstOrder)
    {
        reconstruction_.soundSpeed(thermo.c());
        reconstruction_.reconstructCoupled(patchi, rho, U, p, L, R);
    }
    else
    {
        cellSideStates(patch, rho, U, p, L);

        if (reflecting(patch))
        {
            mirrorStates(patch, wPtr, L, R);

            // The mirror state's e and c are the inner state's (the law
            // of the same rho and p: the same bits, half the evaluations
            // on the wedge and wall patches)
            L.complete(thermo);
            R.e = L.e;
            R.c = L.c;
            return;
        }
        else
        {
            R.rho = rho.boundaryField()[patchi];
            R.U = U.boundaryField()[patchi];
            R.p = p.boundaryField()[patchi];
        }
    }
    L.complete(thermo);
    R.complete(thermo);
}


void Foam::riemannFlux::patchFluxes
(
    const rhoEThermo& thermo,
    const volVectorField& U,
    const label patchi,
    const scalarField* wPtr,
    surfaceScalarField& massFlux,
    surfaceVectorField& momentumFlux,
    surfaceScalarField& energyFlux,
    surfaceScalarField& amaxSf
) const
{
    const fvPatch& patch = mesh_.boundary()[patchi];

    faceStates L, R;
    patchStates(thermo, U, patchi, wPtr, L, R);

    faceFluxes F
    {
        massFlux.boundaryFieldRef()[patchi],
        momentumFlux.boundaryFieldRef()[patchi],
        energyFlux.boundaryFieldRef()[patchi],
        amaxSf.boundaryFieldRef()[patchi]
    };
    solveMoving(L, R, patch.Sf(), patch.magSf(), wPtr, F);
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
    // Normal speed of moving faces [m/s]
    const tmp<surfaceScalarField> tw(faceSpeeds());

    // Internal faces, a block at a time: the cell gradients once (their
    // processor exchange started, overlapping the internal faces), then
    // per block the face states, the law on them and the Riemann solver
    reconstruction_.soundSpeed(thermo.c());
    reconstruction_.startCellGradients(thermo.rho(), U, thermo.p());
    const label nFaces = mesh_.nInternalFaces();
    for (label start = 0; start < nFaces; start += blockSize)
    {
        const label size = min(blockSize, nFaces - start);
        reconstruction_.reconstruct
        (
            start, size, thermo.rho(), U, thermo.p(), L_, R_
        );
        L_.complete(thermo);
        R_.complete(thermo);

        SubList<scalar> mass(massFlux.primitiveFieldRef(), size, start);
        SubList<vector> momentum
        (
            momentumFlux.primitiveFieldRef(), size, start
        );
        SubList<scalar> energy(energyFlux.primitiveFieldRef(), size, start);
        SubList<scalar> amax(amaxSf.primitiveFieldRef(), size, start);
        faceFluxes F{mass, momentum, energy, amax};

        const SubList<vector> Sf(mesh_.Sf().primitiveField(), size, start);
        const SubList<scalar> magSf
        (
            mesh_.magSf().primitiveField(), size, start
        );
        if (tw.valid())
        {
            const SubList<scalar> w(tw().primitiveField(), size, start);
            solveMoving(L_, R_, Sf, magSf, &w, F);
        }
        else
        {
            solveMoving(L_, R_, Sf, magSf, nullptr, F);
        }
    }

    // The neighbour cells' gradients for the coupled patches
    reconstruction_.finishCellGradients();

    // Boundary faces. On a non-coupled patch the inner state is the
    // cell's (rho, U, p) and its e and c the law's at the cell's rho and
    // p: evaluated once per cell (the same function of the same bits as
    // face by face: on a wedge mesh every cell has a front and a back
    // face; issue 18, fluid18), slot[celli] its index in the cells' lists
    const scalarField& rhoc = thermo.rho().primitiveField();
    const vectorField& Uc = U.primitiveField();
    const scalarField& pc = thermo.p().primitiveField();
    labelList slot(mesh_.nCells(), -1);
    DynamicList<label> cells;
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        if (patch.coupled())
        {
            continue;
        }
        for (const label celli : patch.faceCells())
        {
            if (slot[celli] < 0)
            {
                slot[celli] = cells.size();
                cells.append(celli);
            }
        }
    }
    const scalarField cellRho(rhoc, cells);
    const scalarField cellP(pc, cells);
    scalarField cellE(cells.size()), cellC(cells.size());
    thermo.ecFromRhoP(cellRho, cellP, cellE, cellC);

    faceStates L, R;
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        if (patch.size() == 0)
        {
            continue;
        }
        const scalarField* wPtr =
            tw.valid() ? &tw().boundaryField()[patchi] : nullptr;
        if (patch.coupled())
        {
            patchFluxes
            (
                thermo, U, patchi, wPtr,
                massFlux, momentumFlux, energyFlux, amaxSf
            );
            continue;
        }

        faceFluxes F
        {
            massFlux.boundaryFieldRef()[patchi],
            momentumFlux.boundaryFieldRef()[patchi],
            energyFlux.boundaryFieldRef()[patchi],
            amaxSf.boundaryFieldRef()[patchi]
        };

        // A reflecting patch: the cells' states and their mirror images
        // face by face, without the lists of states (the same arithmetic
        // as patchStates' and solveMoving's)
        if (reflecting(patch))
        {
            solveReflecting
            (
                wedgeFaces_ == wedgeFaceModel::cellPressure
             && isA<wedgeFvPatch>(patch),
                patch.faceCells(), rhoc, Uc, pc, slot, cellE, cellC,
                patch.Sf(), patch.magSf(), wPtr, F
            );
            continue;
        }

        // patchStates' states, the cells' e and c taken from their slots
        cellSideStates(patch, rhoc, Uc, pc, L);
        const labelUList& faceCells = patch.faceCells();
        L.e.setSize(faceCells.size());
        L.c.setSize(faceCells.size());
        forAll(faceCells, facei)
        {
            const label i = slot[faceCells[facei]];
            L.e[facei] = cellE[i];
            L.c[facei] = cellC[i];
        }
        R.rho = thermo.rho().boundaryField()[patchi];
        R.U = U.boundaryField()[patchi];
        R.p = thermo.p().boundaryField()[patchi];
        R.complete(thermo);
        solveMoving(L, R, patch.Sf(), patch.magSf(), wPtr, F);
    }
}


void Foam::riemannFlux::wallFluxes
(
    const rhoEThermo& thermo,
    const volVectorField& U,
    const label patchi,
    surfaceScalarField& massFlux,
    surfaceVectorField& momentumFlux,
    surfaceScalarField& energyFlux,
    surfaceScalarField& amaxSf
) const
{
    const fvPatch& patch = mesh_.boundary()[patchi];
    if (patch.coupled())
    {
        FatalErrorInFunction
            << "Patch " << patch.name() << " is coupled: its face states"
            << " are reconstructed with the internal faces (fluxes())"
            << exit(FatalError);
    }

    tmp<scalarField> tw;
    if (mesh_.moving())
    {
        tw = mesh_.phi().boundaryField()[patchi]/patch.magSf();
    }
    patchFluxes
    (
        thermo, U, patchi, tw.valid() ? &tw() : nullptr,
        massFlux, momentumFlux, energyFlux, amaxSf
    );
}


void Foam::riemannFlux::signalSpeeds
(
    const rhoEThermo& thermo,
    const volVectorField& U,
    surfaceScalarField& amaxSf
) const
{
    const tmp<surfaceScalarField> tw(faceSpeeds());

    // Internal faces: the faster of the two cells (w |Sf| = the mesh flux)
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf().primitiveField();
    const scalarField& magSf = mesh_.magSf().primitiveField();
    const vectorField& Uc = U.primitiveField();
    const scalarField& c = thermo.c().primitiveField();
    const scalarField* phiMesh =
        tw.valid() ? &mesh_.phi().primitiveField() : nullptr;
    scalarField& amax = amaxSf.primitiveFieldRef();
    forAll(nei, facei)
    {
        const label o = own[facei], n = nei[facei];
        const scalar wA = phiMesh ? (*phiMesh)[facei] : 0;
        const scalar A = magSf[facei];
        amax[facei] = max
        (
            mag((Uc[o] & Sf[facei]) - wA) + c[o]*A,
            mag((Uc[n] & Sf[facei]) - wA) + c[n]*A
        );
    }

    // Boundary faces: the patch states, first order on coupled patches too
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        if (patch.size() == 0)
        {
            continue;
        }
        const scalarField* wPtr =
            tw.valid() ? &tw().boundaryField()[patchi] : nullptr;

        faceStates L, R;
        patchStates(thermo, U, patchi, wPtr, L, R, true);
        if (wPtr)
        {
            toFaceFrame(L, R, patch.Sf(), patch.magSf(), *wPtr);
        }
        speeds
        (
            L, R, patch.Sf(), patch.magSf(), amaxSf.boundaryFieldRef()[patchi]
        );
    }
}
