/*---------------------------------------------------------------------------*\
Application
    riemannError

Description
    Compares a shock-tube solution with the exact solution of its Riemann
    problem (system/riemannProblemDict, the law of
    constant/thermophysicalProperties; exact solver: src/exactRiemann).

    For each selected time writes postProcessing/riemannError/<time>/
    - profile.dat: x and the computed and exact rho, u (along the tube), p;
    - errors.dat: the number of cells, the L1 norms (volume-weighted means of
      |computed - exact|) of rho, u and p, and the relative errors of the
      star state (pressure at the contact, density midway between each
      non-linear wave and the contact).
    and prints the same.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "inputChecks.H"
#include "inputRecord.H"
#include "runLogFiles.H"
#include "OFstream.H"
#include "rhoEThermoModel.H"
#include "riemannProblem.H"
#include "anyExactRiemannSolver.H"
#include "domainError.H"
#include "caseLock.H"
#include "writeGuard.H"

using namespace Foam;

namespace
{

template<class Law>
bool setLaw(const rhoEThermo& thermo, std::unique_ptr<riemann::AnyEos>& law)
{
    const auto* model = dynamic_cast<const rhoEThermoModel<Law>*>(&thermo);
    if (model)
    {
        law.reset(new riemann::AnyEos(model->law()));
    }
    return model;
}

//- Value of the computed field at the cell nearest to coordinate xi
scalar valueAt(const scalarField& xi, const scalarField& f, const scalar x)
{
    label best = 0;
    forAll(xi, i)
    {
        if (mag(xi[i] - x) < mag(xi[best] - x)) best = i;
    }
    return f[best];
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "L1 errors of a shock-tube solution against the exact solution of"
        " system/riemannProblemDict"
    );
    argList::noParallel();
    timeSelector::addOptions(false, true);
    foamTools::writeGuard::addOption();      // -acceptEdited

    // setRootCase.H with checkCasePath before OpenFOAM checks the case
    #include "setRootCaseChecked.H"
    // one writer per case: a solver running in it (or another utility)
    // is named and nothing is written (adv33 lk10: setRiemannProblem
    // -overwrite removed a running solver's time directories)
    const foamTools::caseLock lock(args);
    foamTools::checkOptions(args);     // no nan, inf or 1e999 in options
    // no directory 'nan' or '1e999' for the Time to take for a time
    foamTools::checkTimeDirectoryNames(args);
    // A number beyond a double's range is a sigFpe inside OpenFOAM's
    // tokenizer: refused first, naming the file and the entry
    foamTools::checkNumbers
    (
        args,
        {
            "system/controlDict",
            "constant/thermophysicalProperties"
        }
    );

    const riemannProblem problem(args.path());

    #include "createTime.H"

    instantList timeDirs = timeSelector::select0(runTime, args);

    // -time of a time that is not there is refused (OpenFOAM's selector
    // takes the nearest); the dictionary must be the one that set the
    // initial fields (issue 19)
    foamTools::requireExistingTimes(args, runTime);
    problem.requireRecordMatches(runTime);

    // The law the results were computed with: each time rhoRiemannFoam
    // wrote records the digest of constant/thermophysicalProperties
    // (<time>/uniform/inputDigests, foamTools::inputRecord); compared with
    // the law now in the case, which the exact solution is computed from
    // (issue 19, adv28 f30: an edited C0 gave errors against another law,
    // exit 0). Checked for every selected time before anything is written
    {
        const fileName thermoFile
        (
            runTime.globalPath()/"constant"/"thermophysicalProperties"
        );
        const std::string key("constant/thermophysicalProperties");
        const std::string now
        (
            foamTools::inputRecord::digest(thermoFile, true)
        );
        for (const instant& t : timeDirs)
        {
            if (!(t.value() > 0))
            {
                continue;
            }
            const fileName record
            (
                runTime.path()/t.name()/"uniform"
               /foamTools::inputRecord::fileName()
            );
            const foamTools::inputRecord::digestMap was
            (
                foamTools::inputRecord::read(record)
            );
            const auto it = was.find(key);
            if (it == was.end())
            {
                WarningInFunction
                    << "no record of the law the results of t = "
                    << t.name() << " s were computed with (" << record
                    << ", written by rhoRiemannFoam since issue 19): "
                    << thermoFile << " is taken as it is, not compared"
                    << nl << endl;
            }
            else if (it->second != now)
            {
                FatalErrorInFunction
                    << thermoFile << " differs from the one the results of"
                    << " t = " << t.name() << " s were computed with (the"
                    << " digest of its entries is " << now.c_str() << ", "
                    << record << " recorded " << it->second.c_str() << "):"
                    << " the errors would measure the change of law, not"
                    << " the solution. Restore the file, or run the solver"
                    << " again with this law (setRiemannProblem, then the"
                    << " solver). Nothing was written" << exit(FatalError);
            }
        }
    }

    // the results compared are the files the solver wrote, on the mesh it
    // computed them on (their digests at the commit, after the records
    // above, which name a changed input as such; adv33 sh22: the old
    // fields compared on a new mesh's cells, exit 0)
    for (const instant& t : timeDirs)
    {
        foamTools::writeGuard::verify
        (
            runTime.path()/t.name(),
            args.found(foamTools::writeGuard::acceptEditedOption()),
            "riemannError"
        );
    }

    #include "createMesh.H"
    problem.checkDiaphragm(mesh);

    // Only times after the start are compared: a case without one has not
    // been run (or its results were removed), which is an error, not a
    // silent success
    label nCompared = 0;
    for (const instant& t : timeDirs)
    {
        if (t.value() > 0) ++nCompared;
    }
    if (nCompared == 0)
    {
        FatalErrorInFunction
            << "no time directory after 0 s selected in " << args.path()
            << " (run the solver first, or check -time/-latestTime)"
            << exit(FatalError);
    }

    forAll(timeDirs, timei)
    {
        runTime.setTime(timeDirs[timei], timei);
        const scalar t = runTime.value();
        if (!(t > 0))
        {
            continue;
        }
        Info<< "Time = " << runTime.timeName() << " s" << endl;
        mesh.readUpdate();

        autoPtr<rhoEThermo> thermo(rhoEThermo::New(mesh));

        std::unique_ptr<riemann::AnyEos> law;
        if
        (
            !setLaw<eos::MieGruneisen>(thermo(), law)
         && !setLaw<eos::StiffenedGas>(thermo(), law)
         && !setLaw<eos::IdealGas>(thermo(), law)
        )
        {
            FatalErrorInFunction
                << "No exact solver for the law " << thermo->lawName()
                << exit(FatalError);
        }

        const volVectorField U
        (
            IOobject("U", runTime.timeName(), mesh, IOobject::MUST_READ),
            mesh
        );
        const vector& d = problem.direction;

        std::unique_ptr<riemann::anyExactRiemannSolver> exact;
        try
        {
            exact.reset
            (
                new riemann::anyExactRiemannSolver
                (
                    *law,
                    {problem.left.rho, problem.left.U & d, problem.left.p},
                    {problem.right.rho, problem.right.U & d, problem.right.p}
                )
            );
        }
        catch (const std::exception& err)
        {
            FatalErrorInFunction
                << "Exact Riemann solver: " << err.what() << exit(FatalError);
        }

        const scalarField& V = mesh.V().field();
        const scalar sumV = gSum(V);
        scalarField xi(mesh.nCells());
        forAll(xi, celli)
        {
            xi[celli] = problem.xi(mesh.C()[celli]);
        }
        const scalarField& rho = thermo->rho().primitiveField();
        const scalarField& p = thermo->p().primitiveField();
        const scalarField u(U.primitiveField() & d);

        scalarField rhoX(xi.size()), uX(xi.size()), pX(xi.size());
        forAll(xi, celli)
        {
            const riemann::sampledState s = exact->sample(xi[celli]/t);
            rhoX[celli] = s.rho;
            uX[celli] = s.u;
            pX[celli] = s.p;
        }

        const scalar L1rho = sum(V*mag(rho - rhoX))/sumV;
        const scalar L1u = sum(V*mag(u - uX))/sumV;
        const scalar L1p = sum(V*mag(p - pX))/sumV;

        // Smooth part: cells farther than a fixed fraction of the wave
        // pattern's extent from every wave edge and the contact (the same
        // physical region on every mesh, for observed orders on smooth
        // solutions)
        const riemann::waveStructure& w = exact->waves();
        const scalar edges[] =
        {
            w.left.headSpeed*t, w.left.tailSpeed*t, w.contactSpeed*t,
            w.right.tailSpeed*t, w.right.headSpeed*t
        };
        scalar extent = 0;
        for (const scalar x : edges) extent = max(extent, mag(x));
        const scalar margin = 0.05*extent;
        scalarField smoothV(V);
        forAll(xi, celli)
        {
            for (const scalar x : edges)
            {
                if (mag(xi[celli] - x) < margin) smoothV[celli] = 0;
            }
        }
        const scalar sumSmoothV = max(sum(smoothV), VSMALL);
        const scalar L1rhoSmooth = sum(smoothV*mag(rho - rhoX))/sumSmoothV;
        const scalar L1pSmooth = sum(smoothV*mag(p - pX))/sumSmoothV;

        // Star state: pressure at the contact; densities midway between
        // the inner edge of each non-linear wave and the contact
        const riemann::starState& star = exact->star();
        const scalar xC = w.contactSpeed*t;
        const scalar xL = 0.5*(w.left.tailSpeed*t + xC);
        const scalar xR = 0.5*(w.right.tailSpeed*t + xC);
        const scalar errPStar =
            mag(valueAt(xi, p, xC) - star.p)
           /max(mag(star.p), max(mag(problem.left.p), mag(problem.right.p)));
        const scalar errRhoL = mag(valueAt(xi, rho, xL) - star.rhoL)/star.rhoL;
        const scalar errRhoR = mag(valueAt(xi, rho, xR) - star.rhoR)/star.rhoR;

        fileName dir =
            runTime.globalPath()/"postProcessing"/"riemannError"
           /runTime.timeName();
        mkDir(dir);
        // Both files written aside, checked, then renamed: a failed write
        // (a full disk) leaves the earlier files, never a cut profile
        // taken for the whole tube (adv33 x12, x15)
        const fileName profileTmp
        (
            dir/("." + word(foamTools::runLogFiles::profileName()) + ".tmp")
        );
        const fileName errorsTmp
        (
            dir/("." + word(foamTools::runLogFiles::errorsName()) + ".tmp")
        );
        bool written = true;
        {
            OFstream os(profileTmp);
            os.precision(12);
            os  << foamTools::runLogFiles::profileHeader()
                << " [kg/m^3]  u uExact [m/s]"
                << "  p pExact [Pa]" << nl;
            labelList order;
            sortedOrder(xi, order);
            for (const label celli : order)
            {
                os  << xi[celli] + problem.x0 << ' '
                    << rho[celli] << ' ' << rhoX[celli] << ' '
                    << u[celli] << ' ' << uX[celli] << ' '
                    << p[celli] << ' ' << pX[celli] << nl;
            }
            os.flush();
            written = written && os.good();
        }
        {
            OFstream os(errorsTmp);
            os.precision(10);
            os  << foamTools::runLogFiles::errorsHeader()
                << "[kg/m^3] L1u[m/s] L1p[Pa]"
                << " relErrPStar relErrRhoStarL relErrRhoStarR"
                << " L1rhoSmooth[kg/m^3] L1pSmooth[Pa]" << nl
                << mesh.nCells() << ' ' << L1rho << ' ' << L1u << ' '
                << L1p << ' ' << errPStar << ' ' << errRhoL << ' '
                << errRhoR << ' ' << L1rhoSmooth << ' ' << L1pSmooth << nl;
            os.flush();
            written = written && os.good();
        }
        if
        (
            !written
         || !Foam::mv(profileTmp, dir/foamTools::runLogFiles::profileName())
         || !Foam::mv(errorsTmp, dir/foamTools::runLogFiles::errorsName())
        )
        {
            Foam::rm(profileTmp);
            Foam::rm(errorsTmp);
            FatalErrorInFunction
                << "cannot write " << dir/"profile.dat" << " and "
                << dir/"errors.dat" << " (is the disk full, or the"
                << " directory not writable?). Nothing was replaced: the"
                << " earlier files, if any, are kept" << exit(FatalError);
        }

        Info<< "    exact star state: p* = " << star.p << " Pa, u* = "
            << star.u << " m/s, rho*L = " << star.rhoL << " kg/m^3, rho*R = "
            << star.rhoR << " kg/m^3" << nl
            << "    waves: left " << riemann::waveTypeName(w.left.type)
            << ", right " << riemann::waveTypeName(w.right.type) << nl
            << "    L1 errors (" << mesh.nCells() << " cells): rho "
            << L1rho << " kg/m^3, u " << L1u << " m/s, p " << L1p << " Pa"
            << nl
            << "    L1 errors away from the wave edges: rho " << L1rhoSmooth
            << " kg/m^3, p " << L1pSmooth << " Pa" << nl
            << "    star state relative errors: p* " << errPStar
            << ", rho*L " << errRhoL << ", rho*R " << errRhoR << nl
            << "    written to " << dir << nl << endl;
    }

    Info<< "End" << endl;

    return 0;
}
