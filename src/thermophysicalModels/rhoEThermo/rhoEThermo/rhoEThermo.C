#include "rhoEThermo.H"
#include "fvMesh.H"
#include "Time.H"
#include "inputChecks.H"
#include "boundaryEvaluation.H"
#include "processorFvPatch.H"

#include <cstdint>
#include <cstring>

namespace Foam
{
    defineTypeNameAndDebug(rhoEThermo, 0);
    defineRunTimeSelectionTable(rhoEThermo, mesh);
}


namespace
{

Foam::IOobject thermoDictIO(const Foam::fvMesh& mesh)
{
    return Foam::IOobject
    (
        "thermophysicalProperties",
        mesh.time().constant(),
        mesh,
        Foam::IOobject::MUST_READ_IF_MODIFIED,
        Foam::IOobject::NO_WRITE
    );
}

Foam::IOobject fieldIO
(
    const Foam::word& name,
    const Foam::fvMesh& mesh,
    Foam::IOobject::readOption r,
    Foam::IOobject::writeOption w
)
{
    return Foam::IOobject(name, mesh.time().timeName(), mesh, r, w);
}

//- Whether a and b are the same double, bit for bit (a signed zero or a
//  NaN's payload included: == would take -0 for +0)
inline bool sameBits(const Foam::scalar a, const Foam::scalar b)
{
    std::uint64_t ia, ib;
    std::memcpy(&ia, &a, sizeof ia);
    std::memcpy(&ib, &b, sizeof ib);
    return ia == ib;
}

} // End anonymous namespace


Foam::rhoEThermo::rhoEThermo(const fvMesh& mesh)
:
    IOdictionary(thermoDictIO(mesh)),
    mesh_(mesh),
    p_(fieldIO("p", mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE), mesh),
    T_(fieldIO("T", mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE), mesh),
    rho_
    (
        fieldIO("rho", mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
        mesh,
        dimensionedScalar(dimDensity, Zero)
    ),
    e_
    (
        fieldIO("e", mesh, IOobject::NO_READ, IOobject::NO_WRITE),
        mesh,
        dimensionedScalar(dimEnergy/dimMass, Zero)
    ),
    c_
    (
        fieldIO("c", mesh, IOobject::NO_READ, IOobject::NO_WRITE),
        mesh,
        dimensionedScalar(dimVelocity, Zero)
    ),
    pFile_(p_.objectPath()),
    TFile_(T_.objectPath())
{
    // was: reset to these, whatever the files said (issue 19)
    foamTools::checkDimensions(p_, dimPressure, "Pa");
    foamTools::checkDimensions(T_, dimTemperature, "K");
}


void Foam::rhoEThermo::correctBoundaryStates(const bool processorStatesSet)
{
    const scalarField& pc = p_.primitiveField();
    const scalarField& Tc = T_.primitiveField();

    // The patches whose states are set here (processor patches whose
    // neighbour states came with the exchange are not)
    auto evaluated = [&](const label patchi)
    {
        return
            !processorStatesSet
         || !isA<processorFvPatch>(mesh_.boundary()[patchi]);
    };

    // A face of a non-coupled patch whose p and T are its cell's, bit for
    // bit (zeroGradient, wedge, slip, symmetry: on a wedge mesh every cell
    // has two such faces, front and back), has the law's state at the
    // cell's p and T: evaluated once per cell (the same function of the
    // same bits, so the same state as face by face; issue 18, fluid18);
    // slot[celli] its index in the cells' lists, -1 if none
    labelList slot(mesh_.nCells(), -1);
    DynamicList<label> slotCells;
    forAll(mesh_.boundary(), patchi)
    {
        if (!evaluated(patchi) || p_.boundaryField()[patchi].coupled())
        {
            continue;
        }
        const scalarField& pp = p_.boundaryField()[patchi];
        const scalarField& Tp = T_.boundaryField()[patchi];
        const labelUList& faceCells = mesh_.boundary()[patchi].faceCells();
        forAll(pp, facei)
        {
            const label celli = faceCells[facei];
            if
            (
                slot[celli] < 0
             && sameBits(pp[facei], pc[celli])
             && sameBits(Tp[facei], Tc[celli])
            )
            {
                slot[celli] = slotCells.size();
                slotCells.append(celli);
            }
        }
    }
    const scalarField slotP(pc, slotCells), slotT(Tc, slotCells);
    scalarField slotRho(slotP.size()), slotE(slotP.size());
    scalarField slotC(slotP.size());
    rhoEFromPT(slotP, slotT, slotRho, slotE);
    cFromRhoE(slotRho, slotE, slotC);
    boolList slotValid(slotP.size());
    forAll(slotValid, i)
    {
        slotValid[i] = valid(slotRho[i], slotE[i]);
    }

    forAll(mesh_.boundary(), patchi)
    {
        if (!evaluated(patchi))
        {
            continue;
        }
        const scalarField& pp = p_.boundaryField()[patchi];
        const scalarField& Tp = T_.boundaryField()[patchi];
        scalarField& rhop = rho_.boundaryFieldRef()[patchi];
        scalarField& ep = e_.boundaryFieldRef()[patchi];
        scalarField& cp = c_.boundaryFieldRef()[patchi];

        if (p_.boundaryField()[patchi].coupled())
        {
            rhoEFromPT(pp, Tp, rhop, ep);
            cFromRhoE(rhop, ep, cp);
            continue;
        }

        // The faces of the cells' states copied, the others evaluated
        // together. The face reported is the first (in face order) whose
        // state is invalid while its cell's is valid: a copied face's
        // validity is its cell's slot's, checked in the copy loop; the
        // others' after their evaluation (the same face as one loop over
        // all faces after both; without a list of the copied faces)
        const labelUList& faceCells = mesh_.boundary()[patchi].faceCells();
        label bad = -1;
        auto badFace = [&](const label facei, const bool faceValid)
        {
            if
            (
                bad < 0
             && !faceValid
             && valid(rho_[faceCells[facei]], e_[faceCells[facei]])
            )
            {
                bad = facei;
            }
        };
        DynamicList<label> own;
        forAll(pp, facei)
        {
            const label celli = faceCells[facei];
            const label i = slot[celli];
            if
            (
                i >= 0
             && sameBits(pp[facei], pc[celli])
             && sameBits(Tp[facei], Tc[celli])
            )
            {
                rhop[facei] = slotRho[i];
                ep[facei] = slotE[i];
                cp[facei] = slotC[i];
                badFace(facei, slotValid[i]);
            }
            else
            {
                own.append(facei);
            }
        }
        if (own.size() == pp.size())
        {
            rhoEFromPT(pp, Tp, rhop, ep);
            cFromRhoE(rhop, ep, cp);
            forAll(rhop, facei)
            {
                badFace(facei, valid(rhop[facei], ep[facei]));
                if (bad >= 0)
                {
                    break;
                }
            }
        }
        else if (own.size())
        {
            const scalarField ownP(pp, own), ownT(Tp, own);
            scalarField ownRho(own.size()), ownE(own.size());
            scalarField ownC(own.size());
            rhoEFromPT(ownP, ownT, ownRho, ownE);
            cFromRhoE(ownRho, ownE, ownC);
            forAll(own, i)
            {
                rhop[own[i]] = ownRho[i];
                ep[own[i]] = ownE[i];
                cp[own[i]] = ownC[i];
            }
            // own in face order: its first bad face, if before the
            // copied faces' first
            const label copiedBad = bad;
            bad = -1;
            forAll(own, i)
            {
                if (copiedBad >= 0 && own[i] > copiedBad)
                {
                    break;
                }
                badFace(own[i], valid(ownRho[i], ownE[i]));
                if (bad >= 0)
                {
                    break;
                }
            }
            if (bad < 0)
            {
                bad = copiedBad;
            }
        }

        if (bad >= 0)
        {
            const label facei = bad;
            FatalErrorInFunction
                << "Invalid thermodynamic state (" << lawName()
                << ") on patch '" << mesh_.boundary()[patchi].name()
                << "' (p: " << p_.boundaryField()[patchi].type()
                << ", T: " << T_.boundaryField()[patchi].type()
                << "), face " << facei << " at "
                << foamTools::numberText
                   (
                       mesh_.boundary()[patchi].Cf()[facei]
                   ).c_str()
                << " m, time " << mesh_.time().timeName() << " s: p = "
                << foamTools::numberText(pp[facei]).c_str() << " Pa, T = "
                << foamTools::numberText(Tp[facei]).c_str() << " K: "
                << reasonPT(pp[facei], Tp[facei]).c_str() << nl
                << "    The boundary values come from the conditions of p"
                << " and T (files " << pFile_ << " and " << TFile_
                << ", boundaryField/" << mesh_.boundary()[patchi].name()
                << ")." << exit(FatalError);
        }
    }
}


void Foam::rhoEThermo::checkInternalPT() const
{
    const scalarField& p = p_.primitiveField();
    const scalarField& T = T_.primitiveField();
    forAll(p, celli)
    {
        if (!valid(rho_[celli], e_[celli]))
        {
            FatalErrorInFunction
                << "Invalid thermodynamic state (" << lawName()
                << ") in cell " << celli << " at "
                << foamTools::numberText(mesh_.C()[celli]).c_str()
                << " m, time " << mesh_.time().timeName() << " s: p = "
                << foamTools::numberText(p[celli]).c_str() << " Pa, T = "
                << foamTools::numberText(T[celli]).c_str()
                << " K: " << reasonPT(p[celli], T[celli]).c_str() << nl
                << "    The state comes from the fields p and T (files "
                << pFile_ << " and " << TFile_ << ", internalField)."
                << exit(FatalError);
        }
    }
}


void Foam::rhoEThermo::correctCells()
{
    pFromRhoE(rho_.primitiveField(), e_.primitiveField(), p_.primitiveFieldRef());
    TFromRhoE(rho_.primitiveField(), e_.primitiveField(), T_.primitiveFieldRef());
    cFromRhoE(rho_.primitiveField(), e_.primitiveField(), c_.primitiveFieldRef());
}


void Foam::rhoEThermo::correct()
{
    correctCells();
    p_.correctBoundaryConditions();
    T_.correctBoundaryConditions();
    correctBoundaryStates();
}


void Foam::rhoEThermo::correct(volVectorField& U)
{
    correctCells();

    // p, T and U to the processor neighbours with one wait; the patches
    // evaluated in correct()'s order, U's after the boundary states (a
    // characteristic boundary of U reads p there)
    foamTools::boundaryEvaluation bc;
    bc.start(p_);
    bc.start(T_);
    bc.start(U);
    // With the combined exchange (parallel): the neighbour cells' rho, e,
    // c with them, on the coupled patches only (the others are set from p
    // and T below); a cyclic patch's evaluate is overwritten there
    const bool exchangeStates = bc.combined();
    if (exchangeStates)
    {
        bc.startCoupled(rho_);
        bc.startCoupled(e_);
        bc.startCoupled(c_);
    }
    bc.finish(p_);
    bc.finish(T_);
    if (exchangeStates)
    {
        bc.finishCoupled(rho_);
        bc.finishCoupled(e_);
        bc.finishCoupled(c_);
    }
    correctBoundaryStates(exchangeStates);
    bc.finish(U);
}


void Foam::rhoEThermo::correctFromPT()
{
    rhoEFromPT
    (
        p_.primitiveField(),
        T_.primitiveField(),
        rho_.primitiveFieldRef(),
        e_.primitiveFieldRef()
    );
    checkInternalPT();
    cFromRhoE(rho_.primitiveField(), e_.primitiveField(), c_.primitiveFieldRef());
    correctBoundaryStates();
}


std::string& Foam::rhoEThermo::implausibleNote()
{
    static std::string note;
    return note;
}


std::string Foam::rhoEThermo::stepHint() const
{
    const Time& runTime = mesh_.time();
    OStringStream os;
    if (!implausibleNote().empty())
    {
        // the likeliest cause first (adv37 w79)
        os  << "    constant/thermophysicalProperties: "
            << implausibleNote().c_str() << nl;
    }
    if (runTime.timeIndex() > runTime.startTimeIndex())
    {
        // after a step: its length is the first suspect (adv32 pr17,
        // pr19: "Invalid thermodynamic state" without naming deltaT)
        os  << "    The step to this time, deltaT = " << runTime.deltaTValue()
            << " s, may have been too long for this state: reduce maxCo"
            << " (adjustTimeStep yes) or deltaT (adjustTimeStep no) of "
            << "system/controlDict, or check the initial and boundary "
            << "conditions." << nl;
    }
    else
    {
        os  << "    Check the initial and boundary conditions." << nl;
    }
    // A constant in other units than the file's is inside its valid
    // range but not the material's (adv37 w79: C0 1.45, km/s for m/s,
    // failed at 1.85 ns naming only the time step)
    os  << "    Check too the constants of the equation of state in "
        << "constant/thermophysicalProperties (their units are SI: a sound"
        << " speed C0 in m/s, a density rho0 in kg/m^3, a pressure in Pa):"
        << " a value in other units is inside the valid range but not the"
        << " material's." << nl;
    return os.str();
}


void Foam::rhoEThermo::checkStates(const string& hint) const
{
    string reason;
    const label celli =
        firstInvalid(rho_.primitiveField(), e_.primitiveField(), reason);

    if (celli >= 0)
    {
        FatalErrorInFunction
            << "Invalid thermodynamic state (" << lawName() << "): "
            << reason.c_str() << nl
            << "    cell " << celli << " at " << mesh_.C()[celli] << " m"
            << ", time " << mesh_.time().timeName() << " s" << nl
            << "    rho = " << rho_[celli] << " kg/m^3, e = " << e_[celli]
            << " J/kg" << nl
            << stepHint().c_str()
            << "    The last written time directory is kept."
            << (hint.empty() ? "" : "\n    ") << hint.c_str()
            << exit(FatalError);
    }
}
