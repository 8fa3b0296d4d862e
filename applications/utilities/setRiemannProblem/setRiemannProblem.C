/*---------------------------------------------------------------------------*\
Application
    setRiemannProblem

Description
    Sets the initial fields p, U and T of a shock-tube case from the two
    states (rho, U, p) of system/riemannProblemDict: T follows from rho and p
    through the equation of state of constant/thermophysicalProperties. The
    boundary conditions in 0/ are kept.

    The fields are written into the case's start time (controlDict's
    startTime, else the earliest time directory), whatever startFrom says:
    never into a result time (issue 19, adv28 f33: with startFrom
    latestTime, the tutorial's, a finished case had p, T and U of its last
    result time replaced by the initial state). A case holding time
    directories after the start time (results of a run from the former
    initial fields) is refused, nothing written, unless -overwrite, which
    removes them first (the option of the solvers, foamTools::resultGuard).
    Each state must lie in the law's domain and, for water (mieGruneisen),
    within the water states the project takes as input: |p| <= 1e10 Pa,
    0 < T <= 1000 K (eos::MieGruneisen::inputPMax, inputTMax, with their
    reasons); checked before anything is removed or written.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include <cmath>
#include <sstream>
#include "inputChecks.H"
#include "rhoEThermo.H"
#include "riemannProblem.H"
#include "resultGuard.H"
#include "writeGuard.H"
#include "MieGruneisen.H"
#include <cstdio>
#include "caseLock.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Set p, U, T of a shock tube from system/riemannProblemDict"
    );
    argList::noParallel();
    foamTools::resultGuard::addOption();

    // setRootCase.H with checkCasePath before OpenFOAM checks the case
    #include "setRootCaseChecked.H"
    // one writer per case: a solver running in it (or another utility)
    // is named and nothing is written (adv33 lk10: setRiemannProblem
    // -overwrite removed a running solver's time directories)
    const foamTools::caseLock lock(args);
    foamTools::checkOptions(args);     // no nan, inf or 1e999 in options
    // A number beyond a double's range is a sigFpe inside OpenFOAM's
    // tokenizer: every file of the case the run reads is scanned first,
    // naming the file, the line and the entry
    foamTools::checkNumbers(args);
    // constant/polyMesh/boundary adding up to the faces of the mesh
    foamTools::checkBoundaryFile(args);

    const riemannProblem problem(args.path());

    #include "createTime.H"
    // The initial fields go to the start time, not to the time startFrom
    // selects (latestTime: a result time)
    DynamicList<fileName> later;
    {
        const scalar t0 = foamTools::resultGuard::caseStartTime(runTime);
        runTime.setTime(t0, 0);
        for (const instant& t : runTime.times())
        {
            if (t.name() != "constant" && t.value() > t0)
            {
                later.append(t.name());
            }
        }
        if (later.size() && !args.found("overwrite"))
        {
            FatalErrorInFunction
                << "The case " << runTime.path() << " holds results of a"
                << " run: " << later.size() << " time director"
                << (later.size() == 1 ? "y" : "ies") << " after the start"
                << " time " << runTime.timeName() << " s ("
                << later.first().c_str()
                << (later.size() > 1 ? " ... " + later.last() : word())
                       .c_str()
                << " s). setRiemannProblem writes the initial fields into "
                << runTime.timeName() << "/; under those results they would"
                << " be the start of another problem." << nl
                << "    Nothing was written. Run it with -overwrite to"
                << " remove the later time directories first, or on a copy"
                << " of the case." << exit(FatalError);
        }
        // -overwrite removes them below: not with a file no run wrote in
        // one (adv36 v32; the rule of the solvers' -overwrite)
        if (later.size())
        {
            DynamicList<fileName> dirs;
            for (const fileName& dir : later)
            {
                dirs.append(runTime.path()/dir);
            }
            foamTools::resultGuard::refuseForeign(dirs, runTime.timeName());
        }
    }
    #include "createMesh.H"
    problem.checkDiaphragm(mesh);



    autoPtr<rhoEThermo> pThermo(rhoEThermo::New(mesh));
    rhoEThermo& thermo = pThermo();

    volVectorField U
    (
        IOobject
        (
            "U",
            runTime.timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        mesh
    );

    // Each side's state must lie in the law's domain: say which side of
    // system/riemannProblemDict is wrong before any cell is set
    for (const word side : {"left", "right"})
    {
        const riemannProblem::state& s =
            side == "left" ? problem.left : problem.right;
        const scalarField rhoS(1, s.rho), pS(1, s.p);
        scalarField eS(1);
        thermo.eFromRhoP(rhoS, pS, eS);
        string reason;
        if (thermo.firstInvalid(rhoS, eS, reason) >= 0)
        {
            FatalErrorInFunction
                << args.path()/"system/riemannProblemDict" << ": state '"
                << side << "' (rho = " << s.rho << " kg/m^3, p = " << s.p
                << " Pa) is outside the domain of the equation of state: "
                << reason << exit(FatalError);
        }
        // What is written (p, T, in 17 digits) and the energy the solver
        // computes from it (rho e) within the numbers OpenFOAM's reader
        // takes (foamTools::outsideReaderRange, the solvers' own check of
        // 0/): a state the law takes beyond them (p = 1e300 Pa of an
        // ideal gas) was written and then refused by the solver at 0/p
        // (adv52 p16)
        {
            scalarField TS(1);
            thermo.TFromRhoE(rhoS, eS, TS);
            const std::pair<const char*, scalar> written[] =
            {
                {"p", s.p}, {"T", TS[0]}, {"rho e", s.rho*eS[0]}
            };
            for (const auto& w : written)
            {
                std::ostringstream os;
                os.precision(17);
                os << w.second;
                if
                (
                    !std::isfinite(w.second)
                 || foamTools::outsideReaderRange(os.str()) > 0
                )
                {
                    FatalErrorInFunction
                        << args.path()/"system/riemannProblemDict"
                        << ": state '" << side << "' (rho = "
                        << foamTools::numberText(s.rho).c_str()
                        << " kg/m^3, p = "
                        << foamTools::numberText(s.p).c_str() << " Pa): "
                        << (std::string(w.first) == "p" ? "p" :
                            std::string(w.first) + ", which follows from "
                            "rho and p,").c_str()
                        << " = " << os.str().c_str() << " "
                        << foamTools::readerRangeText(1).c_str()
                        << ": the solver could not read the state back. Give"
                        << " entry 'p' of '" << side << "' a smaller"
                        << " magnitude (the law "
                        << thermo.lawName().c_str() << " takes it, the"
                        << " numbers of the case cannot hold it)."
                        << nl << "    Nothing was written."
                        << exit(FatalError);
                }
            }
        }
        // Water: the states the law is used for (eos::MieGruneisen::
        // inputPMax, inputTMax; adv29 f19: p 5e70 Pa set T 1.2e65 K)
        if (thermo.lawName() == eos::MieGruneisen::typeName)
        {
            scalarField TS(1);
            thermo.TFromRhoE(rhoS, eS, TS);
            const scalar pMax = eos::MieGruneisen::inputPMax;
            const scalar TMax = eos::MieGruneisen::inputTMax;
            if (!(mag(s.p) <= pMax) || !(TS[0] > 0 && TS[0] <= TMax))
            {
                const auto g = [](const scalar x)
                {
                    char buf[32];
                    std::snprintf(buf, sizeof(buf), "%g", x);
                    return std::string(buf);
                };
                FatalErrorInFunction
                    << args.path()/"system/riemannProblemDict" << ": state"
                    << " '" << side << "' (rho = " << s.rho << " kg/m^3, p"
                    << " = " << g(s.p).c_str() << " Pa: T = "
                    << g(TS[0]).c_str() << " K) is outside the water"
                    << " states the mieGruneisen law is used for: |p| <= "
                    << g(pMax).c_str() << " Pa and T in (0, "
                    << g(TMax).c_str() << "] K (a fit for liquid water:"
                    << " its linear Us-Up Hugoniot and the liquid's"
                    << " constant Cv; the"
                    << " reasons in src/eos/MieGruneisen.H, inputPMax)."
                    << nl << "    Nothing was written." << exit(FatalError);
            }
        }
    }

    // -overwrite: the later time directories go only now, once the mesh,
    // the diaphragm, the law and both states have been read and checked
    // (adv29 f02c, f02d, f21, f22: a diaphragm outside the tube, a
    // direction across it, no thermophysicalProperties or no mesh removed
    // the results and then refused)
    for (const fileName& dir : later)
    {
        rmDir(runTime.path()/dir);
    }
    if (later.size())
    {
        Info<< "-overwrite: removed " << later.size() << " time"
            << " director" << (later.size() == 1 ? "y" : "ies")
            << " after the start time " << runTime.timeName() << " s"
            << nl << endl;
    }

    scalarField& rho = thermo.rho().primitiveFieldRef();
    scalarField& p = thermo.p().primitiveFieldRef();
    const vectorField& C = mesh.C().primitiveField();

    forAll(C, celli)
    {
        const riemannProblem::state& s =
            problem.xi(C[celli]) < 0 ? problem.left : problem.right;
        rho[celli] = s.rho;
        p[celli] = s.p;
        U[celli] = s.U;
    }

    thermo.eFromRhoP(rho, p, thermo.e().primitiveFieldRef());
    thermo.TFromRhoE
    (
        rho,
        thermo.e().primitiveField(),
        thermo.T().primitiveFieldRef()
    );
    thermo.checkStates();

    thermo.p().correctBoundaryConditions();
    thermo.T().correctBoundaryConditions();
    U.correctBoundaryConditions();

    // Each field checked whole on disk, or the earlier fields kept (a full
    // disk cut them, exit 0)
    foamTools::writeChecked({&thermo.p(), &thermo.T(), &U});
    // What set the fields: riemannError compares the dictionary with it
    // (an edited dictionary was compared silently with the fields of the
    // former one; issue 19)
    problem.writeRecord(runTime.timePath()/"uniform"/"riemannProblem");

    Info<< "Left  state: rho " << problem.left.rho << " kg/m^3, U "
        << problem.left.U << " m/s, p " << problem.left.p << " Pa" << nl
        << "Right state: rho " << problem.right.rho << " kg/m^3, U "
        << problem.right.U << " m/s, p " << problem.right.p << " Pa" << nl
        << "Diaphragm at " << problem.x0 << " m along "
        << problem.direction << nl << "End" << endl;

    return 0;
}
