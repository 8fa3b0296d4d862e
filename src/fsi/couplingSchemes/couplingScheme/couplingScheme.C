#include "couplingScheme.H"
#include "error.H"
#include "inputChecks.H"

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
        foamTools::readInRangeOrDefault<label>
        (
            dict, "maxIter", "", 1, foamTools::noUpperBound<label>(), true, 30
        )
    ),
    tolerance_
    (
        // A relative residual: 0.1 already lets a pass with a tenth of
        // the interface velocity wrong count as converged; 1e3 made every
        // first pass converge, silently (issue 19)
        foamTools::readInRangeOrDefault<scalar>
        (
            dict, "tolerance", "", 0, 0.1, false, 1e-6
        )
    ),
    velocityScale_
    (
        foamTools::readInRangeOrDefault<scalar>
        (
            dict, "velocityScale", "m/s", 0,
            foamTools::noUpperBound<scalar>(), false, 1e-2
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
    const word action(dict.getOrDefault<word>("onNonConvergence", "warn"));
    if (action == "stop")
    {
        stopOnNonConvergence_ = true;
    }
    else if (action != "warn")
    {
        FatalIOErrorInFunction(dict)
            << "onNonConvergence " << action << " is not valid; valid:"
            << " (warn stop)" << exit(FatalIOError);
    }

    const word predictor
    (
        dict.getOrDefault<word>("predictor", "centralDifference")
    );
    if (predictor == "extrapolated")
    {
        extrapolate_ = true;
    }
    else if (predictor != "centralDifference")
    {
        FatalIOErrorInFunction(dict)
            << "predictor " << predictor << " is not valid; valid:"
            << " (centralDifference extrapolated)" << exit(FatalIOError);
    }
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

    // The extrapolated predictor's history (a state written with the
    // centralDifference predictor has none: the first step after the
    // restart takes centralDifference)
    previousAcceleration_.clear();
    previousDeltaT_ = 0;
    if (extrapolate_ && dict.found("previousAcceleration"))
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
