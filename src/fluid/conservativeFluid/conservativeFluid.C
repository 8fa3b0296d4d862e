#include "conservativeFluid.H"
#include "fvc.H"
#include "wedgePolyPatch.H"
#include "keywordCheck.H"
#include "inputChecks.H"
#include "subDict.H"
#include "physicalBounds.H"
#include "OStringStream.H"
#include "writeGuard.H"

#include <cfenv>
#include <cmath>
#include <iostream>
#include <unistd.h>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- The Time at time t [s] while this object lives (the boundary
//  conditions of a Runge-Kutta stage's state evaluated at the stage's
//  time: OpenFOAM's time-dependent patches read the mesh's Time, not an
//  argument), then back to its value, bit for bit (also when an error
//  throws). Only the value (TimeState's, a dimensionedScalar's): the
//  time's name, index and step stay the step's (messages name the step's
//  end)
class stageTime
{
    Foam::Time& runTime_;
    const Foam::scalar value_;

public:

    stageTime(Foam::Time& runTime, const Foam::scalar t)
    :
        runTime_(runTime),
        value_(runTime.value())
    {
        runTime_.value() = t;
    }

    ~stageTime()
    {
        runTime_.value() = value_;
    }

    stageTime(const stageTime&) = delete;
    void operator=(const stageTime&) = delete;
};


//- riemann{} of system/fvSolution after the keyword check: ours, in a
//  dictionary of OpenFOAM (whose other entries are not checked)
const Foam::dictionary& checkedRiemannDict(const Foam::fvMesh& mesh)
{
    using namespace Foam;

    const dictionary& solution = mesh.solutionDict();
    foamTools::checkDuplicates(solution, {"riemann"});
    const dictionary& dict = foamTools::subDict(solution, "riemann");
    wordList valid{"riemannSolver", "timeScheme", "viscous", "wedgeFaces"};
    // A switch: OpenFOAM took any number for one (viscous 2 or 0.5 was
    // "yes" without a word; adv pass rk40)
    if (dict.found("viscous", keyType::LITERAL))
    {
        const ITstream& is = dict.lookup("viscous");
        const bool ok =
            is.size() == 1
         && (
                (is[0].isWord() && Switch(is[0].wordToken(), true).valid())
             || (is[0].isLabel() && (is[0].labelToken() == 0
                                  || is[0].labelToken() == 1))
            );
        if (!ok)
        {
            FatalIOErrorInFunction(dict)
                << "entry 'viscous' is not a switch: valid values are yes,"
                << " no, true, false, on, off (or 1, 0)"
                << exit(FatalIOError);
        }
    }
    if (dict.getOrDefault<Switch>("viscous", false))
    {
        valid.append("mu");
    }
    foamTools::checkKeywords(dict, valid);
    return dict;
}

//- U as read, its dimensions checked before any expression uses it (was:
//  OpenFOAM's "different dimensions" error in rhoE's, naming no file)
const Foam::volVectorField& checkedVelocity(const Foam::volVectorField& U)
{
    using namespace Foam;
    foamTools::checkDimensions(U, dimVelocity, "m/s");
    // Each component finite and below physicalBounds::velocityMax before
    // any expression squares it: 1e300 m/s in 0/U ended in a
    // floating-point exception in magSqr(U) (issue 19, adv30 hg14)
    const scalar uMax = physicalBounds::velocityMax;
    auto bad = [uMax](const vector& u)
    {
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (!std::isfinite(u[d]) || !(std::abs(u[d]) < uMax))
            {
                return true;
            }
        }
        return false;
    };
    auto refuse = [&](const word& where, const vector& u)
    {
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__, U.objectPath(), -1
        )   << "field U: " << where << " has U = "
            << foamTools::numberText(u).c_str() << " m/s; each component"
            << " must be finite with magnitude below "
            << foamTools::numberText(uMax).c_str() << " m/s"
            << exit(FatalIOError);
    };
    forAll(U.primitiveField(), celli)
    {
        if (bad(U.primitiveField()[celli]))
        {
            refuse("cell " + Foam::name(celli), U.primitiveField()[celli]);
        }
    }
    forAll(U.boundaryField(), patchi)
    {
        const fvPatchVectorField& pf = U.boundaryField()[patchi];
        forAll(pf, facei)
        {
            if (bad(pf[facei]))
            {
                refuse
                (
                    "boundaryField " + pf.patch().name() + ", face "
                  + Foam::name(facei), pf[facei]
                );
            }
        }
    }
    return U;
}

//- The stop of a check that every rank makes of its own part (the
//  restart state's files and cells): text is this rank's message, empty
//  when its part is good; item names what is bad (-1: nothing), as
//  describe(item) in the master's list; summary follows that list.
//  Decided by every rank together (adv49b i23: the rank with the bad
//  cell stopped, the others went on into the first exchange and died in
//  MPI with MPI_ERR_TRUNCATE): returns on every rank if every part is
//  good. In parallel a bad rank other than the master prints its own
//  text first, whole and flushed, and only then tells the master, which
//  stops the run naming the bad ranks; the other ranks wait for that
//  stop (adv50a k02 (c), (d), adv49b i23: a good rank's "no state of the
//  fluid on another rank" only, the bad rank's text lost to that rank's
//  abort in 5 of 5 runs). Texts are not sent through OpenFOAM's streams
//  (fix19g's gathered List<string> failed there: "Wrong token type -
//  expected string, found word ''")
template<class Describe>
void stopTogether
(
    const std::string& text,
    const Foam::label item,
    const Describe& describe,
    const std::string& summary
)
{
    using namespace Foam;
    bool anyBad = !text.empty();
    if (Pstream::parRun())
    {
        reduce(anyBad, orOp<bool>());
    }
    if (!anyBad)
    {
        return;
    }
    const char* const nothingRun =
        ". Nothing was run: restart from an earlier time, or start anew";
    if (!Pstream::parRun())
    {
        FatalErrorInFunction
            << text.c_str() << nothingRun << exit(FatalError);
    }
    if (!text.empty() && !Pstream::master())
    {
        // one write of the whole text (stderr is unbuffered: each << was
        // a write of its own, which the master's output could split,
        // lead L01 of session 47)
        const std::string whole
        (
            "\n--> FOAM FATAL ERROR (rank "
          + std::to_string(Pstream::myProcNo()) + "): " + text + nothingRun
          + "\n\n"
        );
        std::cerr.write(whole.data(), std::streamsize(whole.size()));
        std::cerr.flush();
    }
    labelList badItem(Pstream::nProcs(), -1);
    badItem[Pstream::myProcNo()] = text.empty() ? -1 : max(item, label(0));
    Pstream::listCombineGather(badItem, maxEqOp<label>());
    if (!Pstream::master())
    {
        foamTools::waitForMastersStop();
    }
    FatalErrorInFunction;
    if (!text.empty())
    {
        FatalError << "rank 0: " << text.c_str();
    }
    label nOther = 0;
    forAll(badItem, proci)
    {
        if (proci != Pstream::myProcNo() && badItem[proci] >= 0)
        {
            FatalError
                << (nOther++ ? ", " : !text.empty() ? "\n    and " : "")
                << "rank " << proci << " ("
                << describe(badItem[proci]).c_str() << ")";
        }
    }
    if (nOther)
    {
        FatalError << ": " << summary.c_str();
    }
    FatalError << nothingRun << exit(FatalError);
}


//- The files of the conservative state (rho, rhoU, rhoE) of the time
//  mesh starts from, as a bit set (1: rho, 2: rhoU, 4: rhoE)
const char* const stateFiles[3] = {"rho", "rhoU", "rhoE"};

std::string stateFilesText(const Foam::label set)
{
    std::string text;
    for (int i = 0; i < 3; ++i)
    {
        if (set & (1 << i))
        {
            text += (text.empty() ? "" : ", ") + std::string(stateFiles[i]);
        }
    }
    return text;
}


//- Whether the run restarts from the conservative state rho, rhoU, rhoE
//  of the time mesh starts from (else from p, U, T), decided by every
//  rank together. A file of the three that is there but whose header
//  OpenFOAM cannot read (damaged, or of another class) was taken for no
//  file: the run restarted from p, U and T without a word, and in
//  parallel the rank with such a file took that way while the others
//  checked their state with every rank (adv50a k02 (f): rank 1's rhoE
//  with its first bytes overwritten, -acceptEdited: the ranks out of
//  step, OpenFOAM's "error in IOstream ... List<fileName>" of a later
//  exchange, no file named). Refused naming the file, as is a time our
//  solvers committed that holds some of the three but not all, and a
//  rank without them while other ranks have them
bool conservativeRestart(const Foam::fvMesh& mesh)
{
    using namespace Foam;
    const word& t = mesh.time().timeName();
    const fileName dir(mesh.time().timePath());
    label there = 0, unreadable = 0;
    {
        IOobject io("rho", t, mesh);
        if (isFile(dir/"rho"))
        {
            there |= 1;
            unreadable |= io.typeHeaderOk<volScalarField>(true) ? 0 : 1;
        }
    }
    {
        IOobject io("rhoU", t, mesh);
        if (isFile(dir/"rhoU"))
        {
            there |= 2;
            unreadable |= io.typeHeaderOk<volVectorField>(true) ? 0 : 2;
        }
    }
    {
        IOobject io("rhoE", t, mesh);
        if (isFile(dir/"rhoE"))
        {
            there |= 4;
            unreadable |= io.typeHeaderOk<volScalarField>(true) ? 0 : 4;
        }
    }
    const bool committed =
        isFile(dir/foamTools::writeGuard::committedName(), false);
    // this rank's way: 1 the conservative state, 0 p, U, T
    const label way = there == 7 && !unreadable ? 1 : 0;
    label anyConservative = way;
    if (Pstream::parRun())
    {
        reduce(anyConservative, maxOp<label>());
    }
    std::string text;
    label item = -1;
    if (unreadable)
    {
        item = unreadable;
        text = "the file(s) " + stateFilesText(unreadable) + " of the"
            " restart time " + t + " s (" + dir + ") are there but are no"
            " field OpenFOAM can read: the header (FoamFile { ... class"
            " volScalarField or volVectorField; ... }) is damaged or of"
            " another class; the conservative state rho, rhoU, rhoE would"
            " not be read (the run would restart from p, U and T, not"
            " continue the run that wrote the time)";
    }
    else if (there != 0 && there != 7 && committed)
    {
        item = 7 & ~there;
        text = "the restart time " + t + " s (" + dir + "), written by a"
            " run of ours, has " + stateFilesText(there) + " but not "
          + stateFilesText(item) + ": the conservative state rho, rhoU,"
            " rhoE is the three files (removed or moved after the run"
            " wrote them?); without them the run would restart from p, U"
            " and T, not continue the run that wrote the time";
    }
    else if (!way && anyConservative)
    {
        item = 7 & ~there;
        text = "the restart time " + t + " s (" + dir + ") has no "
          + stateFilesText(item) + " while the other ranks' times have"
            " the conservative state rho, rhoU, rhoE: the ranks would"
            " restart in two ways";
    }
    stopTogether
    (
        text, item,
        [](const label set) { return stateFilesText(set); },
        "the conservative state's files of the restart time " + t + " s"
        " cannot be used there; each such rank's message, printed above"
        " as \"FOAM FATAL ERROR (rank N)\", names the files"
    );
    return way;
}

//- runTime, the mesh's Time (the one whose value the stages set)
Foam::Time& meshTime(Foam::Time& runTime, const Foam::fvMesh& mesh)
{
    if (&runTime != &mesh.time())
    {
        FatalErrorInFunction
            << "the Time given is not the mesh's: the fluid's stages would"
            << " set the time of another run than the boundary conditions"
            << " read" << Foam::exit(Foam::FatalError);
    }
    return runTime;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::conservativeFluid::conservativeFluid(Time& runTime, fvMesh& mesh)
:
    runTime_(meshTime(runTime, mesh)),
    mesh_(mesh),
    thermo_(rhoEThermo::New(mesh)),
    U_
    (
        IOobject
        (
            "U",
            mesh.time().timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        mesh
    ),
    rhoU_
    (
        IOobject
        (
            "rhoU",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        thermo_->rho()*checkedVelocity(U_)
    ),
    rhoE_
    (
        IOobject
        (
            "rhoE",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        thermo_->rho()*(thermo_->e() + 0.5*magSqr(U_))
    ),
    flux_(riemannFlux::New(mesh, checkedRiemannDict(mesh))),
    rk_(foamTools::subDict(mesh.solutionDict(), "riemann")),
    viscous_
    (
        foamTools::subDict(mesh.solutionDict(), "riemann")
       .lookupOrDefault<Switch>("viscous", false)
    ),
    mu_("mu", dimDynamicViscosity, Zero),
    cpuViscous_(0),
    phi_
    (
        IOobject("phi", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimMass/dimTime, Zero)
    ),
    phiU_
    (
        IOobject("phiU", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector(dimForce, Zero)
    ),
    phiE_
    (
        IOobject("phiE", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimPower, Zero)
    ),
    amaxSf_
    (
        IOobject("amaxSf", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimVolume/dimTime, Zero)
    ),
    swirlDirection_(Zero)
{
    // The conservative state of a written time: a restart continues
    // exactly (bitwise with writePrecision 17 and writeControl timeStep)
    const word& t = mesh.time().timeName();
    if (conservativeRestart(mesh))
    {
        Info<< "Restarting from the conservative state rho, rhoU, rhoE of"
            << " time " << t << " s" << nl << endl;
        // The digits the time was written with are checked before
        // (foamTools::writeGuard::checkRestartDigits, adv50b k58)
        const volScalarField rhoWritten
        (
            IOobject
            (
                "rho",
                t,
                mesh,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            ),
            mesh
        );
        checkRestartState(rhoWritten);
        thermo_->rho().primitiveFieldRef() = rhoWritten.primitiveField();
        correctPrimitives();
    }
    thermo_->checkStates();

    if (viscous_)
    {
        const dictionary& riemannDict =
            foamTools::subDict(mesh.solutionDict(), "riemann");
        mu_.read(riemannDict);
        // finite, the viscosity bound of every reader (physicalBounds.H:
        // a modulus times a time; was [0, inf), adv pass rk40)
        const scalar muMax = physicalBounds::viscosityMax;
        if (!(mu_.value() >= 0 && mu_.value() < muMax))
        {
            FatalIOErrorInFunction(riemannDict)
                << "mu = " << mu_.value() << " Pa s is outside the valid"
                << " range [0, " << muMax << ") Pa s" << exit(FatalIOError);
        }
        Info<< "Newtonian viscous stress with mu = " << mu_.value()
            << " Pa s" << nl << endl;
    }

    forAll(mesh.boundaryMesh(), patchi)
    {
        if (isA<wedgePolyPatch>(mesh.boundaryMesh()[patchi]))
        {
            swirlDirection_ =
                refCast<const wedgePolyPatch>(mesh.boundaryMesh()[patchi])
               .centreNormal();
            break;
        }
    }
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::conservativeFluid::checkRestartState
(
    const volScalarField& rhoWritten
) const
{
    // A state that is none of the fluid's (an edited or damaged rho, rhoU
    // or rhoE used with -acceptEdited): a density not in (0, inf) (was: a
    // floating-point exception in correctPrimitives, adv47a f07; a NaN
    // passed the ordered comparison's trap only after it, adv48a h01 (i)),
    // or primitives that are not finite or outside the law's domain (rho
    // 1e-290: rhoE/rho overflowed in correctPrimitives, adv48a h01 (h)).
    // The arithmetic of correctPrimitives with the floating-point traps
    // held, so that an overflow is found here, not trapped: a FatalError
    // naming the time, the cell, the state and why, before anything uses
    // it
    const scalarField& rho = rhoWritten.primitiveField();
    const vectorField& rhoU = rhoU_.primitiveField();
    const scalarField& rhoE = rhoE_.primitiveField();
    scalarField e(rho.size(), Zero);
    label bad = -1;
    std::string why;
    vector Ubad(Zero);
    {
        std::fenv_t env;
        std::feholdexcept(&env);
        const scalar uMax = physicalBounds::velocityMax;
        forAll(rho, celli)
        {
            const scalar r = rho[celli];
            // finiteness first: an ordered comparison with a NaN traps
            if (!std::isfinite(r) || !(r > 0))
            {
                bad = celli;
                why = "the density rho is no state of the fluid (valid "
                    "range (0, inf) kg/m^3)";
                break;
            }
            const vector U(rhoU[celli]/r);
            const scalar magU =
                std::sqrt(U.x()*U.x() + U.y()*U.y() + U.z()*U.z());
            if (!std::isfinite(magU) || !(magU < uMax))
            {
                bad = celli;
                Ubad = U;
                why = "the velocity rhoU/rho is not finite or not below "
                    "the bound of every reader (physicalBounds::velocityMax,"
                    " 1e+05 m/s)";
                break;
            }
            e[celli] = rhoE[celli]/r - 0.5*magU*magU;
            if (!std::isfinite(e[celli]))
            {
                bad = celli;
                Ubad = U;
                why = "the specific internal energy rhoE/rho - |U|^2/2 is "
                    "not finite";
                break;
            }
        }
        if (bad < 0)
        {
            string reason;
            bad = thermo_->firstInvalid(rho, e, reason);
            if (bad >= 0)
            {
                Ubad = rhoU[bad]/rho[bad];
                why = "no state of the equation of state (" + reason + ")";
            }
        }
        // The sound speed the first step computes with, finite and below
        // the bound of every reader: a state inside the law's domain but
        // of no fluid (rho 1e-290 kg/m^3 at 1e5 Pa, c ~ 1e147 m/s)
        // trapped in the first step's face states (adv49a j03: sigFpe in
        // eFromRhoP, exit 136)
        if (bad < 0)
        {
            scalarField c(rho.size(), Zero);
            thermo_->cFromRhoE(rho, e, c);
            const scalar cMax = physicalBounds::soundSpeedMax;
            forAll(c, celli)
            {
                if (!std::isfinite(c[celli]) || !(c[celli] < cMax))
                {
                    bad = celli;
                    Ubad = rhoU[celli]/rho[celli];
                    why = "the sound speed of the state, c = "
                      + foamTools::numberText(c[celli]) + " m/s, is not finite "
                        "or not below the bound of every reader "
                        "(physicalBounds::soundSpeedMax, 1e+05 m/s): no "
                        "fluid's state";
                    break;
                }
            }
        }
        std::feclearexcept(FE_ALL_EXCEPT);
        std::fesetenv(&env);
    }
    // Decided by every rank together (adv49b i23: the rank with the bad
    // cell stopped, the others went on into the first exchange and died
    // in MPI with MPI_ERR_TRUNCATE): each rank's verdict reduced; a rank
    // whose cells are good stops too
    bool anyBad = bad >= 0;
    if (Pstream::parRun())
    {
        reduce(anyBad, orOp<bool>());
    }
    if (bad < 0 && !anyBad)
    {
        return;
    }
    // The cell centres, made by every rank together: the first use of
    // the mesh's geometry exchanges the processor patches' face centres
    // with the neighbour ranks, and made by the bad rank alone (for its
    // text) it left a message the master then took for the next one
    // (MPI_ERR_TRUNCATE; fix19g's gathered texts: "Wrong token type")
    const vectorField& centres = mesh_.C().primitiveField();
    // This rank's text (empty: its cells are good)
    OStringStream text;
    Ostream& os = text;
    if (bad >= 0)
    {
        os<< "the conservative state of the restart time "
            << mesh_.time().timeName() << " s in cell " << bad << " (at "
            << foamTools::numberText(centres[bad]).c_str() << " m): rho = "
            << foamTools::numberText(rho[bad]).c_str() << " kg/m^3 ("
            << rhoWritten.objectPath().c_str() << "), rhoU = "
            << foamTools::numberText(rhoU[bad]).c_str()
            << " kg/(m^2 s), rhoE = "
            << foamTools::numberText(rhoE[bad]).c_str() << " J/m^3";
        if (why.compare(0, 15, "the density rho") != 0)
        {
            os<< " (U = " << foamTools::numberText(Ubad).c_str() << " m/s";
            if (why.compare(0, 16, "the velocity rho") != 0)
            {
                os<< ", e = " << foamTools::numberText(e[bad]).c_str()
                    << " J/kg";
            }
            os<< ")";
        }
        os<< ": " << why.c_str() << "; the files rho, rhoU, rhoE of the time "
            << "were edited or damaged after the run wrote them";
    }
    stopTogether
    (
        text.str(), bad,
        [](const label celli) { return "cell " + Foam::name(celli); },
        "the conservative state of the restart time "
      + mesh_.time().timeName() + " s is no state of the fluid there; each"
        " such rank's message, printed above as \"FOAM FATAL ERROR (rank"
        " N)\", names the cell, the state and the files"
    );
}


void Foam::conservativeFluid::addViscousTerms
(
    vectorField& divPhiU,
    scalarField& divPhiE
) const
{
    cpuViscousTimer_.cpuTimeIncrement();
    const volTensorField tauMC("tauMC", mu_*dev2(T(fvc::grad(U_))));

    divPhiU -=
        fvc::laplacian(mu_, U_)().primitiveField()
      + fvc::div(tauMC)().primitiveField();

    const surfaceScalarField sigmaDotU
    (
        (
            mu_*mesh_.magSf()*fvc::snGrad(U_)
          + fvc::dotInterpolate(mesh_.Sf(), tauMC)
        )
      & fvc::interpolate(U_)
    );

    divPhiE -= fvc::div(sigmaDotU)().primitiveField();
    cpuViscous_ += cpuViscousTimer_.cpuTimeIncrement();
}


Foam::tmp<Foam::vectorField>
Foam::conservativeFluid::wallViscousForce(const label patchi) const
{
    const fvPatch& patch = mesh_.boundary()[patchi];
    if (patch.coupled())
    {
        FatalErrorInFunction
            << "Patch " << patch.name() << " is coupled: no wall"
            << exit(FatalError);
    }
    if (!viscous_)
    {
        return tmp<vectorField>::New(patch.size(), Zero);
    }
    cpuViscousTimer_.cpuTimeIncrement();
    // The patch values of addViscousTerms' two parts: the Laplacian's
    // mu |Sf| snGrad(U) and div(tauMC)'s Sf . tauMC (Gauss: tauMC's patch
    // value, from the gradient's patch value, the cell's with its normal
    // part replaced by the patch's snGrad)
    const volTensorField gradU(fvc::grad(U_));
    const tensorField& gradUp = gradU.boundaryField()[patchi];
    const tensorField tauMC(mu_.value()*dev2(gradUp.T()));
    tmp<vectorField> tF
    (
        -(
            mu_.value()*patch.magSf()*U_.boundaryField()[patchi].snGrad()
          + (patch.Sf() & tauMC)
        )
    );
    cpuViscous_ += cpuViscousTimer_.cpuTimeIncrement();
    return tF;
}


void Foam::conservativeFluid::divergences
(
    scalarField& divPhi,
    vectorField& divPhiU,
    scalarField& divPhiE
) const
{
    // fvc::surfaceIntegrate of the three fluxes in one face loop: each
    // cell's sums in its order (the internal faces, then the patches),
    // then divided by the cell volume: the same bits
    divPhi = Zero;
    divPhiU = Zero;
    divPhiE = Zero;
    const labelUList& owner = mesh_.owner();
    const labelUList& neighbour = mesh_.neighbour();
    const scalarField& phi = phi_.primitiveField();
    const vectorField& phiU = phiU_.primitiveField();
    const scalarField& phiE = phiE_.primitiveField();
    forAll(owner, facei)
    {
        const label own = owner[facei];
        const label nei = neighbour[facei];
        divPhi[own] += phi[facei];
        divPhi[nei] -= phi[facei];
        divPhiU[own] += phiU[facei];
        divPhiU[nei] -= phiU[facei];
        divPhiE[own] += phiE[facei];
        divPhiE[nei] -= phiE[facei];
    }
    forAll(mesh_.boundary(), patchi)
    {
        const labelUList& faceCells = mesh_.boundary()[patchi].faceCells();
        const scalarField& pPhi = phi_.boundaryField()[patchi];
        const vectorField& pPhiU = phiU_.boundaryField()[patchi];
        const scalarField& pPhiE = phiE_.boundaryField()[patchi];
        forAll(mesh_.boundary()[patchi], facei)
        {
            const label celli = faceCells[facei];
            divPhi[celli] += pPhi[facei];
            divPhiU[celli] += pPhiU[facei];
            divPhiE[celli] += pPhiE[facei];
        }
    }
    const scalarField& V = mesh_.V().field();
    divPhi /= V;
    divPhiU /= V;
    divPhiE /= V;

    if (viscous_)
    {
        addViscousTerms(divPhiU, divPhiE);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::conservativeFluid::fluxes()
{
    flux_->fluxes(thermo_(), U_, phi_, phiU_, phiE_, amaxSf_);
}


void Foam::conservativeFluid::wallFluxes(const label patchi)
{
    flux_->wallFluxes(thermo_(), U_, patchi, phi_, phiU_, phiE_, amaxSf_);
}


void Foam::conservativeFluid::signalSpeeds()
{
    flux_->signalSpeeds(thermo_(), U_, amaxSf_);
}


Foam::scalar Foam::conservativeFluid::courantNumber(const scalar deltaT) const
{
    return courantNumber
    (
        deltaT, returnReduce(localCourantRate(), maxOp<scalar>())
    );
}


Foam::scalar Foam::conservativeFluid::courantNumber
(
    const scalar deltaT,
    const scalar rate
) const
{
    const scalar CoNum = rate*deltaT;

    Info<< "Courant number max: " << CoNum << endl;

    return CoNum;
}


Foam::scalar Foam::conservativeFluid::localCourantRate() const
{
    tmp<surfaceScalarField> tspeedSf(amaxSf_);
    if (viscous_)
    {
        tspeedSf = amaxSf_ + viscousSpeedSf();
    }
    const surfaceScalarField& speedSf = tspeedSf();

    // fvc::surfaceSum's cell sums, in its order (the same bits), without
    // its processor-patch exchange (the vol field's boundary values are
    // not used)
    scalarField sumSpeedSf(mesh_.nCells(), Zero);
    const labelUList& owner = mesh_.owner();
    const labelUList& neighbour = mesh_.neighbour();
    forAll(owner, facei)
    {
        sumSpeedSf[owner[facei]] += speedSf[facei];
        sumSpeedSf[neighbour[facei]] += speedSf[facei];
    }
    forAll(mesh_.boundary(), patchi)
    {
        const labelUList& pFaceCells = mesh_.boundary()[patchi].faceCells();
        const fvsPatchScalarField& pssf = speedSf.boundaryField()[patchi];
        forAll(pFaceCells, facei)
        {
            sumSpeedSf[pFaceCells[facei]] += pssf[facei];
        }
    }

    // 0.5 max(x) is max(0.5 x) to the bit
    return 0.5*max(sumSpeedSf/mesh_.V().field());
}


Foam::tmp<Foam::surfaceScalarField>
Foam::conservativeFluid::viscousSpeedSf() const
{
    // (8/3) nu/d: the explicit diffusion limit of longitudinal waves
    // (diffusivity 4/3 nu) as a speed, d the distance of the centres
    tmp<surfaceScalarField> tspeedSf
    (
        (8.0/3.0)*mu_/fvc::interpolate(thermo_->rho())
       *mesh_.magSf()*mesh_.deltaCoeffs()
    );

    // A wedge face couples its cell with the cell's own value rotated by
    // the wedge's angle theta: there the Laplacian's stiffness is the hoop
    // term's, about nu/r^2 (r the cell centre's distance from the axis),
    // not (8/3) nu |Sf| deltaCoeffs/V = (8/3) nu/((r theta/2) r theta),
    // which is 1/theta^2 times larger (525 at 5 deg: the 2D preview's
    // viscous step was 5.9e-12 s, set by its cells at the axis;
    // docs/results/blast3D.md, "The paper's water viscosity"). Each of
    // the pair carries (8/3) nu V/r^2, so that the pair adds (8/3) nu/r^2
    // to the cell's rate (localCourantRate's 0.5 sum / V), the r-z
    // faces' (8/3) for the hoop term's nu/r^2
    surfaceScalarField& speedSf = tspeedSf.ref();
    const volScalarField& rho = thermo_->rho();
    forAll(mesh_.boundaryMesh(), patchi)
    {
        const polyPatch& pp = mesh_.boundaryMesh()[patchi];
        if (!isA<wedgePolyPatch>(pp))
        {
            continue;
        }
        // the wedge's axis through the origin (OpenFOAM's wedge)
        const vector& axis = refCast<const wedgePolyPatch>(pp).axis();
        const labelUList& faceCells = mesh_.boundary()[patchi].faceCells();
        scalarField& ps = speedSf.boundaryFieldRef()[patchi];
        forAll(faceCells, facei)
        {
            const label celli = faceCells[facei];
            const vector& C = mesh_.C()[celli];
            const scalar r2 = magSqr(C - (C & axis)*axis);
            ps[facei] =
                (8.0/3.0)*mu_.value()/rho[celli]*mesh_.V()[celli]
               /max(r2, VSMALL);
        }
    }
    return tspeedSf;
}


Foam::scalar Foam::conservativeFluid::viscousDeltaT(const scalar maxCo) const
{
    if (!viscous_)
    {
        return GREAT;
    }
    const scalar rate = 0.5*gMax
    (
        fvc::surfaceSum(viscousSpeedSf())().primitiveField()
       /mesh_.V().field()
    );
    return rate > 0 ? maxCo/rate : GREAT;
}


void Foam::conservativeFluid::storeOldState()
{
    rho0_ = thermo_->rho().primitiveField();
    rhoU0_ = rhoU_.primitiveField();
    rhoE0_ = rhoE_.primitiveField();
    V0_ = mesh_.V().field();
}


void Foam::conservativeFluid::restoreOldState()
{
    thermo_->rho().primitiveFieldRef() = rho0_;
    rhoU_.primitiveFieldRef() = rhoU0_;
    rhoE_.primitiveFieldRef() = rhoE0_;
    // The state of the step's start: its boundary values at that time
    // (the next stage 0's fluxes use them; the Time is at the step's end)
    const stageTime start
    (
        runTime_, runTime_.value() - runTime_.deltaTValue()
    );
    correctPrimitives();
}


void Foam::conservativeFluid::correctPrimitives()
{
    const scalarField& rho = thermo_->rho().primitiveField();
    const vectorField& rhoU = rhoU_.primitiveField();
    const scalarField& rhoE = rhoE_.primitiveField();
    vectorField& U = U_.primitiveFieldRef();
    scalarField& e = thermo_->e().primitiveFieldRef();

    // Cell by cell, the arithmetic of U = rhoU/rho, e = rhoE/rho
    // - 0.5 |U|^2 without the temporary fields of the expressions
    forAll(rho, celli)
    {
        U[celli] = rhoU[celli]/rho[celli];
        e[celli] = rhoE[celli]/rho[celli] - 0.5*magSqr(U[celli]);
    }

    // The thermo first: a characteristic boundary (planeWaveInflow) sets
    // U there from the cells' new p as well as their U; the processor
    // values of p, T and U in one exchange
    thermo_->correct(U_);
}


void Foam::conservativeFluid::step(const scalar dt)
{
    scalarField divPhi(mesh_.nCells());
    vectorField divPhiU(mesh_.nCells());
    scalarField divPhiE(mesh_.nCells());

    volScalarField& rho = thermo_->rho();

    for (label stage = 0; stage < rk_.nStages(); ++stage)
    {
        if (stage > 0)
        {
            // An invalid stage state stops here with the cell named (not
            // as a floating-point exception in the flux)
            thermo_->checkStates();
            fluxes();
        }

        const scalar a = rk_.a(stage);

        divergences(divPhi, divPhiU, divPhiE);

        // In place, cell by cell: the arithmetic of the field expression
        // a q0 + (1 - a)(q - dt divF) in its order, without its temporary
        // fields (two of them at a time, 48 B per cell for rho U)
        const scalar b = 1 - a;
        scalarField& rhoc = rho.primitiveFieldRef();
        vectorField& rhoUc = rhoU_.primitiveFieldRef();
        scalarField& rhoEc = rhoE_.primitiveFieldRef();
        forAll(rhoc, celli)
        {
            rhoc[celli] =
                a*rho0_[celli] + b*(rhoc[celli] - dt*divPhi[celli]);
            rhoUc[celli] =
                a*rhoU0_[celli] + b*(rhoUc[celli] - dt*divPhiU[celli]);
            rhoEc[celli] =
                a*rhoE0_[celli] + b*(rhoEc[celli] - dt*divPhiE[celli]);
        }

        // The boundary values of the stage's state at its time
        // (rungeKuttaScheme::c; the Time is at the step's end)
        const stageTime at
        (
            runTime_, runTime_.value() - (1 - rk_.c(stage))*dt
        );
        correctPrimitives();
    }
}


Foam::scalar Foam::conservativeFluid::aleStep
(
    const scalar dt,
    const string& hint
)
{
    // Swept volume of each cell over the step [m^3]
    scalarField dV(mesh_.nCells(), Zero);
    fvc::surfaceIntegrate(dV, mesh_.phi());
    dV *= dt*mesh_.V().field();

    scalarField Vk(V0_);

    scalarField divPhi(mesh_.nCells());
    vectorField divPhiU(mesh_.nCells());
    scalarField divPhiE(mesh_.nCells());

    volScalarField& rho = thermo_->rho();

    for (label stage = 0; stage < rk_.nStages(); ++stage)
    {
        const scalar a = rk_.a(stage);

        fluxes();
        divergences(divPhi, divPhiU, divPhiE);

        // In place, cell by cell: the arithmetic of the field expressions
        // (a V0 q0 + (1 - a)(Vk q - dt V divF))/Vnew in their order, and
        // the swirl removed, without their temporary fields (seven per
        // stage)
        const scalar b = 1 - a;
        const scalarField& V = mesh_.V().field();
        scalarField& rhoc = rho.primitiveFieldRef();
        vectorField& rhoUc = rhoU_.primitiveFieldRef();
        scalarField& rhoEc = rhoE_.primitiveFieldRef();
        const bool swirl = mag(swirlDirection_) > 0;
        forAll(rhoc, celli)
        {
            const scalar V0 = V0_[celli];
            const scalar Vkc = Vk[celli];
            const scalar Vnew = a*V0 + b*(Vkc + dV[celli]);
            const scalar dtV = dt*V[celli];
            rhoc[celli] =
                (a*V0*rho0_[celli] + b*(Vkc*rhoc[celli] - dtV*divPhi[celli]))
               /Vnew;
            vector rhoUi =
                (
                    a*V0*rhoU0_[celli]
                  + b*(Vkc*rhoUc[celli] - dtV*divPhiU[celli])
                )/Vnew;
            if (swirl)
            {
                rhoUi -= (rhoUi & swirlDirection_)*swirlDirection_;
            }
            rhoUc[celli] = rhoUi;
            rhoEc[celli] =
                (
                    a*V0*rhoE0_[celli]
                  + b*(Vkc*rhoEc[celli] - dtV*divPhiE[celli])
                )/Vnew;
            Vk[celli] = Vnew;
        }

        // The boundary values of the stage's state at its time
        // (rungeKuttaScheme::c; the Time is at the step's end)
        {
            const stageTime at
            (
                runTime_, runTime_.value() - (1 - rk_.c(stage))*dt
            );
            correctPrimitives();
        }

        // An invalid stage state (a diverging coupling first shows here)
        // stops with the cell and the time named, before a flux turns it
        // into a floating-point exception
        thermo_->checkStates(hint);
    }

    return max(mag(Vk - mesh_.V().field())/mesh_.V().field());
}


// ************************************************************************* //
