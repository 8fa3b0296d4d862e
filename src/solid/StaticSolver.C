#include "StaticSolver.H"
#include "SolidError.H"

#ifdef SOLID_HAVE_UMFPACK
#include <Eigen/UmfPackSupport>
#else
#include <Eigen/SparseLU>
#endif
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <ostream>




namespace
{

#ifdef SOLID_HAVE_UMFPACK
using LinearSolver = Eigen::UmfPackLU<Eigen::SparseMatrix<double>>;
#else
using LinearSolver = Eigen::SparseLU<Eigen::SparseMatrix<double>>;
#endif

} // namespace


struct solid::StaticSolver::LinearCache
{
    LinearSolver lu;
    std::vector<int> outer, inner;

    bool samePattern(const Eigen::SparseMatrix<double>& K) const
    {
        return int(outer.size()) == K.outerSize() + 1
            && int(inner.size()) == K.nonZeros()
            && std::equal(outer.begin(), outer.end(), K.outerIndexPtr())
            && std::equal(inner.begin(), inner.end(), K.innerIndexPtr());
    }

    void storePattern(const Eigen::SparseMatrix<double>& K)
    {
        outer.assign(K.outerIndexPtr(), K.outerIndexPtr() + K.outerSize() + 1);
        inner.assign(K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros());
    }
};


solid::StaticSolver::StaticSolver
(
    Model& model,
    const NewtonSettings& settings
)
:
    model_(model),
    set_(settings),
    linear_(new LinearCache)
{}


solid::StaticSolver::~StaticSolver() = default;


namespace
{

struct Norms
{
    double residual;    // normalised combined residual
    double merit;
};

} // namespace


bool solid::StaticSolver::newton
(
    double dt,
    std::vector<IterationRecord>& hist,
    std::string& reason,
    StepReport& rep
)
{
    using clock = std::chrono::steady_clock;
    auto seconds = [](clock::time_point a)
    {
        return std::chrono::duration<double>(clock::now() - a).count();
    };
    Model& m = model_;
    const int nu = m.nDisplacementDofs();
    const int nm = m.nMultipliers();
    const int nf = m.nFree();
    const auto& fi = m.freeIndex();
    const double t = m.time + dt;

    Eigen::VectorXd x = m.u;
    Eigen::VectorXd p = m.pressure;
    m.applyDirichlet(x, t);

    // Reference volume per multiplier (constraint scaling)
    Eigen::VectorXd Vm(nm);
    for (int e = 0; e < m.mesh().nElements(); ++e)
    {
        if (m.multiplierOf(e) >= 0) Vm(m.multiplierOf(e)) = m.geometry(e).V;
    }
    double uScale = 0;
    for (int e = 0; e < m.mesh().nElements(); ++e)
    {
        uScale = std::max(uScale, std::cbrt(std::abs(m.geometry(e).V)));
    }
    uScale *= 1e-12;

    Assembly a;
    Eigen::VectorXd R(nf);
    double Fref = 0;
    auto evaluate = [&](const Eigen::VectorXd& xx, const Eigen::VectorXd& pp,
                        bool tangent) -> Norms
    {
        const auto t0 = clock::now();
        m.assemble(xx, pp, t, dt, tangent, a);
        rep.assemblySeconds += seconds(t0);
        const Eigen::VectorXd r = a.fint - a.fext;
        double ru2 = 0, rp2 = 0, react2 = 0;
        for (int i = 0; i < nu; ++i)
        {
            if (fi[i] >= 0)
            {
                R(fi[i]) = r(i);
                ru2 += r(i)*r(i);
            }
            else
            {
                react2 += r(i)*r(i);
            }
        }
        for (int k = 0; k < nm; ++k)
        {
            R(fi[nu + k]) = a.constraint(k);
            rp2 = std::max(rp2, std::abs(a.constraint(k))/Vm(k));
        }
        Fref = std::max({Fref, a.fext.norm(), std::sqrt(react2)});
        const double F = Fref > 0 ? Fref : 1.0;
        Norms n;
        n.residual = std::max(std::sqrt(ru2)/F, rp2);
        n.merit = ru2/(F*F) + rp2*rp2;
        return n;
    };

    Norms n;
    try
    {
        n = evaluate(x, p, true);
    }
    catch (const SolidError& e)
    {
        if (!e.recoverable()) throw;
        reason = e.what();
        return false;
    }

    Eigen::SparseMatrix<double> K(nf, nf);
    LinearSolver& lu = linear_->lu;
    double update = std::numeric_limits<double>::infinity();
    for (int it = 0; it < set_.maxIterations; ++it)
    {
        if (n.residual <= set_.tolResidual && update <= set_.tolDisplacement)
        {
            m.u = x;
            m.pressure = p;
            return true;
        }
        // Reduced tangent
        const auto ts = clock::now();
        Triplets red;
        red.reserve(a.K.size());
        for (const auto& tr : a.K)
        {
            const int r = fi[tr.row()], c = fi[tr.col()];
            if (r >= 0 && c >= 0) red.emplace_back(r, c, tr.value());
        }
        K.setFromTriplets(red.begin(), red.end());
        // Symbolic analysis only when the sparsity pattern changes (e.g. a
        // contact set): kept across iterations and steps
        K.makeCompressed();
        if (!linear_->samePattern(K))
        {
            lu.analyzePattern(K);
            linear_->storePattern(K);
        }
        lu.factorize(K);
        if (lu.info() != Eigen::Success)
        {
            reason = "singular tangent matrix (check the Dirichlet "
                     "conditions: rigid-body modes?)";
            return false;
        }
        const Eigen::VectorXd rhs = -R;
        const Eigen::VectorXd dx = lu.solve(rhs);
        rep.solveSeconds += seconds(ts);

        // Line search on the merit function
        Eigen::VectorXd xt = x, pt = p;
        double alpha = 1, bestAlpha = 0, bestMerit = n.merit;
        Norms nt{};
        bool ok = false;
        // Near round-off the merit cannot decrease reliably: a residual
        // already below tolerance takes the full (tiny) correction
        const bool search = set_.lineSearch && n.residual > set_.tolResidual;
        for (int ls = 0; ls <= (search ? set_.maxLineSearch : 0); ++ls)
        {
            xt = x;
            pt = p;
            for (int i = 0; i < nu; ++i)
                if (fi[i] >= 0) xt(i) += alpha*dx(fi[i]);
            for (int k = 0; k < nm; ++k) pt(k) += alpha*dx(fi[nu + k]);
            try
            {
                nt = evaluate(xt, pt, true);
                if (nt.merit <= (1 - 1e-4*alpha)*n.merit || !search)
                {
                    ok = true;
                    break;
                }
                if (nt.merit < bestMerit)
                {
                    bestMerit = nt.merit;
                    bestAlpha = alpha;
                }
            }
            catch (const SolidError& e)
            {
                if (!e.recoverable()) throw;
                reason = e.what();
            }
            alpha *= 0.5;
        }
        if (!ok)
        {
            if (bestAlpha == 0)
            {
                if (reason.empty()) reason = "line search failed";
                return false;
            }
            alpha = bestAlpha;
            xt = x;
            pt = p;
            for (int i = 0; i < nu; ++i)
                if (fi[i] >= 0) xt(i) += alpha*dx(fi[i]);
            for (int k = 0; k < nm; ++k) pt(k) += alpha*dx(fi[nu + k]);
            nt = evaluate(xt, pt, true);
        }
        double du2 = 0;
        for (int i = 0; i < nu; ++i)
            if (fi[i] >= 0) du2 += std::pow(alpha*dx(fi[i]), 2);
        update = std::sqrt(du2)/std::max(xt.norm(), uScale);
        hist.push_back({it, n.residual, update, alpha});
        if (set_.log)
        {
            *set_.log << "    Newton " << it << ": residual " << n.residual
                << " -> " << nt.residual << ", update " << update
                << ", alpha " << alpha << '\n';
        }
        x = xt;
        p = pt;
        n = nt;
    }
    if (n.residual <= set_.tolResidual && update <= set_.tolDisplacement)
    {
        m.u = x;
        m.pressure = p;
        return true;
    }
    reason = "Newton did not converge in " + std::to_string(set_.maxIterations)
        + " iterations (normalised residual " + std::to_string(n.residual)
        + ")";
    return false;
}


solid::StepReport solid::StaticSolver::step(double dt)
{
    Model& m = model_;
    StepReport rep;
    const double tEnd = m.time + dt;
    double h = dt;
    int cuts = 0;
    while (m.time < tEnd - 1e-12*dt)
    {
        h = std::min(h, tEnd - m.time);
        std::vector<IterationRecord> hist;
        std::string reason;
        const Eigen::VectorXd u0 = m.u;
        bool ok = newton(h, hist, reason, rep);
        for (int aug = 0; ok && aug < set_.maxAugmentations; ++aug)
        {
            bool changed = false;
            for (const auto& c : m.contributions())
            {
                changed = c->augment(m, m.u, m.time + h) || changed;
            }
            if (!changed) break;
            ++rep.augmentations;
            ok = newton(h, hist, reason, rep);
            if (aug + 1 == set_.maxAugmentations)
            {
                ok = false;
                reason = "augmented-Lagrangian loop did not converge in "
                    + std::to_string(set_.maxAugmentations) + " passes";
            }
        }
        rep.iterations += int(hist.size());
        if (ok)
        {
            m.v = (m.u - u0)/h;
            m.time += h;
            m.commit();
            rep.subSteps++;
            rep.lastHistory = hist;
            if (set_.log)
            {
                *set_.log << "  t = " << m.time << " s: converged in "
                    << hist.size() << " iterations\n";
            }
        }
        else
        {
            m.revert();
            m.u = u0;
            if (++cuts > set_.maxCuts)
            {
                throw SolidError
                (
                    SolidError::Kind::notConverged,
                    "static step from t = " + std::to_string(m.time)
                  + " s failed after " + std::to_string(set_.maxCuts)
                  + " step cuts (last dt = " + std::to_string(h)
                  + " s): " + reason
                );
            }
            if (set_.log)
            {
                *set_.log << "  step cut to dt = " << h/2 << " s: " << reason
                    << '\n';
            }
            h *= 0.5;
        }
    }
    rep.cuts = cuts;
    rep.time = m.time;
    return rep;
}


Eigen::VectorXd solid::StaticSolver::reactions()
{
    Model& m = model_;
    Assembly a;
    m.assemble(m.u, m.pressure, m.time, 0, false, a);
    m.revert();
    Eigen::VectorXd r = a.fint - a.fext;
    for (int i = 0; i < m.nDisplacementDofs(); ++i)
    {
        if (m.freeIndex()[i] >= 0) r(i) = 0;
    }
    return r;
}
