#include "couplingScheme.H"
#include "error.H"
#include "inputChecks.H"
#include "fsiRanges.H"

#include <cmath>

namespace Foam
{
    defineTypeNameAndDebug(couplingScheme, 0);
    defineRunTimeSelectionTable(couplingScheme, dictionary);
}


Foam::couplingScheme::couplingScheme(const dictionary& dict)
:
    maxIter_
    (
        fsiRanges::readOrDefault<label>(dict, "coupling", "maxIter", 30)
    ),
    tolerance_
    (
        // A relative residual: 0.1 already lets a pass with a tenth of
        // the interface velocity wrong count as converged; 1e3 made every
        // first pass converge, silently (issue 19)
        fsiRanges::readOrDefault<scalar>
        (
            dict, "coupling", "tolerance", 1e-6
        )
    ),
    velocityScale_
    (
        fsiRanges::readOrDefault<scalar>
        (
            dict, "coupling", "velocityScale", 1e-2
        )
    ),
    stopOnNonConvergence_(false),
    iter_(0),
    residual_(0),
    converged_(true),
    nSteps_(0),
    nNonConverged_(0),
    nIterations_(0),
    maxIterUsed_(0),
    extrapolate_(false),
    previousDeltaT_(0),
    startDeltaT_(0)
{
    // Words named with the file, the line and the closest valid word
    // (adv48b g39: "onNonConvergence Stop is not valid; valid: (warn stop)")
    stopOnNonConvergence_ =
        foamTools::readOneOfOrDefault
        (
            dict, "onNonConvergence", {"warn", "stop"}, "warn"
        ) == "stop";
    extrapolate_ =
        foamTools::readOneOfOrDefault
        (
            dict, "predictor", {"centralDifference", "extrapolated"},
            "centralDifference"
        ) == "extrapolated";
}


void Foam::couplingScheme::beginStep()
{
    iter_ = 0;
    residual_ = 0;
    converged_ = false;
    newStep();
}


Foam::tmp<Foam::scalarField> Foam::couplingScheme::predict
(
    const scalarField& v0,
    const scalarField& a0,
    const scalar dt
)
{
    if (extrapolate_)
    {
        startAcceleration_ = a0;
        startDeltaT_ = dt;
    }
    if (!extrapolate_ || previousAcceleration_.empty())
    {
        // v_n + dt/2 a_n, the arithmetic of the solver's former predictor
        return v0 + 0.5*dt*a0;
    }
    if (previousAcceleration_.size() != a0.size())
    {
        FatalErrorInFunction
            << "predictor extrapolated: the previous step's interface"
            << " accelerations (previousAcceleration of the restart state"
            << " uniform/fsiState) have " << previousAcceleration_.size()
            << " values, the interface " << a0.size() << " dofs"
            << exit(FatalError);
    }

    // a_n+1 = a_n + (a_n - a_n-1) dt/dt_n-1; x = v_n + dt/4 (a_n + a_n+1)
    const scalar ratio = dt/previousDeltaT_;
    tmp<scalarField> tx(new scalarField(v0.size()));
    scalarField& x = tx.ref();
    forAll(x, i)
    {
        const scalar aNext = a0[i] + ratio*(a0[i] - previousAcceleration_[i]);
        x[i] = v0[i] + 0.25*dt*(a0[i] + aNext);
    }
    return tx;
}


bool Foam::couplingScheme::update
(
    scalarField& x,
    const scalarField& xTilde,
    const scalarField& beta
)
{
    ++iter_;
    const scalarField r(xTilde - x);
    residual_ = max(mag(r))/max(max(mag(xTilde)), velocityScale_);

    if (!iterative())
    {
        converged_ = true;
        return true;
    }
    if (residual_ <= tolerance_)
    {
        converged_ = true;
        return true;
    }
    if (iter_ >= maxIter_)
    {
        converged_ = false;
        return true;
    }
    relax(x, xTilde, r, beta);
    return false;
}


void Foam::couplingScheme::endStep(const scalar time)
{
    ++nSteps_;
    nIterations_ += iter_;
    if (extrapolate_)
    {
        previousAcceleration_.transfer(startAcceleration_);
        previousDeltaT_ = startDeltaT_;
    }
    maxIterUsed_ = max(maxIterUsed_, iter_);
    if (!converged_)
    {
        ++nNonConverged_;
        if (stopOnNonConvergence_)
        {
            FatalErrorInFunction
                << "FSI coupling did not converge at t = " << time
                << " s: residual " << residual_ << " after " << iter_
                << " iterations (onNonConvergence stop)" << exit(FatalError);
        }
        WarningInFunction
            << "FSI coupling not converged at t = " << time << " s: residual "
            << residual_ << " after " << iter_ << " iterations (step "
            << nNonConverged_ << " of " << nSteps_ << " not converged)"
            << endl;
    }
}


void Foam::couplingScheme::report(Ostream& os) const
{
    os  << "FSI coupling " << type() << ": " << nSteps_ << " steps, "
        << nIterations_ << " iterations (mean "
        << scalar(nIterations_)/max(nSteps_, 1) << ", max " << maxIterUsed_
        << "), " << nNonConverged_ << " steps not converged" << endl;
}


void Foam::couplingScheme::writeState(Ostream& os) const
{
    os.writeEntry
    (
        "couplingStatistics",
        labelList({nSteps_, nIterations_, maxIterUsed_, nNonConverged_})
    );
    // The predictor that wrote the state: a state of the extrapolated
    // predictor after a step holds its history, one of centralDifference
    // none (readState tells a history lost from one never written)
    os.writeEntry
    (
        "predictor",
        word(extrapolate_ ? "extrapolated" : "centralDifference")
    );
    if (extrapolate_ && !previousAcceleration_.empty())
    {
        os.writeEntry("previousAcceleration", previousAcceleration_);
        os.writeEntry("previousDeltaT", previousDeltaT_);
    }
}


void Foam::couplingScheme::readState(const dictionary& dict)
{
    const labelList s(dict.get<labelList>("couplingStatistics"));
    if (s.size() != 4)
    {
        FatalIOErrorInFunction(dict)
            << "couplingStatistics needs 4 values (steps, iterations, max"
            << " iterations, steps not converged), not " << s.size()
            << exit(FatalIOError);
    }
    nSteps_ = s[0];
    nIterations_ = s[1];
    maxIterUsed_ = s[2];
    nNonConverged_ = s[3];

    // The extrapolated predictor's history: its two entries together; a
    // state of the extrapolated predictor after a step has them (lost:
    // refused, also with -acceptEdited, a missing entry being no edited
    // value); a state written with the centralDifference predictor (or by
    // a build that did not say which) has none: the first step after the
    // restart takes centralDifference, said (adv49b i11: the history
    // missing was taken as none without a word; one entry missing was
    // OpenFOAM's "Entry 'previousDeltaT' not found")
    previousAcceleration_.clear();
    previousDeltaT_ = 0;
    const bool hasA = dict.found("previousAcceleration");
    const bool hasDt = dict.found("previousDeltaT");
    if (hasA != hasDt)
    {
        FatalIOErrorInFunction(dict)
            << "entry '" << (hasA ? "previousDeltaT" : "previousAcceleration")
            << "' is missing beside entry '"
            << (hasA ? "previousAcceleration" : "previousDeltaT")
            << "': the extrapolated predictor's history is written as both."
            << " The state is damaged: restore the file, or restart from an"
            << " earlier time" << exit(FatalIOError);
    }
    const word wrote(dict.getOrDefault<word>("predictor", word::null));
    if (extrapolate_ && !hasA)
    {
        if (wrote == "extrapolated" && nSteps_ > 0)
        {
            FatalIOErrorInFunction(dict)
                << "entries 'previousAcceleration' and 'previousDeltaT' are"
                << " missing: the state was written with predictor "
                << "extrapolated after " << nSteps_ << " steps, which writes"
                << " them (the predictor's history). Without them the first"
                << " step would take the centralDifference predictor and the"
                << " results would differ from the run's: restore the file,"
                << " or restart from an earlier time" << exit(FatalIOError);
        }
        WarningInFunction
            << dict.name().c_str() << " holds no history of the "
            << "extrapolated predictor (it was written with predictor "
            << (
                   wrote.empty()
                 ? std::string("centralDifference, or by an earlier build")
                 : std::string(wrote)
               ).c_str()
            << "): the first step after the restart takes the "
            << "centralDifference predictor, so the results differ from "
            << "those of an uninterrupted run with predictor extrapolated"
            << nl << endl;
    }
    if (extrapolate_ && hasA)
    {
        previousAcceleration_ = dict.get<scalarField>("previousAcceleration");
        previousDeltaT_ = dict.get<scalar>("previousDeltaT");
        bool finite = std::isfinite(previousDeltaT_) && previousDeltaT_ > 0;
        for (const scalar a : previousAcceleration_)
        {
            finite = finite && std::isfinite(a);
        }
        if (!finite)
        {
            FatalIOErrorInFunction(dict)
                << "previousDeltaT must be > 0 s and previousAcceleration"
                << " finite (the extrapolated predictor's history); got"
                << " previousDeltaT = " << previousDeltaT_ << " s"
                << exit(FatalIOError);
        }
    }
}
