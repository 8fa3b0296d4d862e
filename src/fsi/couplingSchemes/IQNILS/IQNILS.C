#include "IQNILS.H"
#include "fsiRanges.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"

#include <Eigen/Dense>

namespace Foam
{
    defineTypeNameAndDebug(IQNILS, 0);
    addToRunTimeSelectionTable(couplingScheme, IQNILS, dictionary);
}


Foam::IQNILS::IQNILS(const dictionary& dict)
:
    couplingScheme(dict),
    omega0_
    (
        fsiRanges::readOrDefault<scalar>
        (
            dict, "coupling", "initialRelaxation", 0.1
        )
    ),
    reuse_
    (
        fsiRanges::readOrDefault<label>(dict, "coupling", "reuse", 0)
    )
{}


void Foam::IQNILS::newStep()
{
    rPrev_.clear();
    xTildePrev_.clear();
    rBest_ = GREAT;
    nStall_ = 0;
    // Keep the columns of the last reuse_ steps (stepColumns_: per step,
    // newest first)
    stepColumns_.push_front(0);
    std::size_t keep = 0;
    for (std::size_t s = 1; s < stepColumns_.size() && label(s) <= reuse_; ++s)
    {
        keep += stepColumns_[s];
    }
    stepColumns_.resize(std::min(stepColumns_.size(), std::size_t(reuse_ + 1)));
    V_.resize(std::min(V_.size(), keep));
    W_.resize(std::min(W_.size(), keep));
}


void Foam::IQNILS::relax
(
    scalarField& x,
    const scalarField& xTilde,
    const scalarField& r,
    const scalarField&
)
{
    // Stagnation: drop the columns, relax again
    const scalar rNorm = max(mag(r));
    if (rNorm < 0.999*rBest_)
    {
        rBest_ = rNorm;
        nStall_ = 0;
    }
    else if (++nStall_ >= 4 && !V_.empty())
    {
        V_.clear();
        W_.clear();
        for (label& n : stepColumns_) n = 0;
        rPrev_.clear();
        xTildePrev_.clear();
        rBest_ = rNorm;
        nStall_ = 0;
        x += omega0_*r;
        return;
    }

    if (rPrev_.size() == r.size())
    {
        V_.push_front(scalarField(r - rPrev_));
        W_.push_front(scalarField(xTilde - xTildePrev_));
        ++stepColumns_[0];
    }
    rPrev_ = r;
    xTildePrev_ = xTilde;

    if (V_.empty())
    {
        x += omega0_*r;
        return;
    }

    const label n = r.size(), m = label(V_.size());
    Eigen::MatrixXd V(n, m);
    Eigen::VectorXd rhs(n);
    for (label i = 0; i < n; ++i)
    {
        rhs(i) = -r[i];
        for (label j = 0; j < m; ++j) V(i, j) = V_[j][i];
    }
    const Eigen::VectorXd c = V.colPivHouseholderQr().solve(rhs);
    x = xTilde;
    for (label j = 0; j < m; ++j) x += c(j)*W_[j];
}
