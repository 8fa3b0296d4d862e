#include "Viscoelastic.H"
#include "SolidError.H"
#include "physicalBounds.H"

#include <cmath>
#include <limits>

solid::Viscoelastic::Viscoelastic
(
    std::unique_ptr<IsochoricModel> base,
    const std::vector<MaxwellBranch>& branches,
    const std::string& context
)
:
    base_(std::move(base)),
    branches_(branches)
{
    const double mu0 = base_->shearModulus();
    if (!branches_.empty() && !(mu0 > 0))
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            context + ": Maxwell branches scale the equilibrium energy and "
            "need C10 > 0 (entry 'C10')"
        );
    }
    for (std::size_t a = 0; a < branches_.size(); ++a)
    {
        const std::string n = std::to_string(a + 1);
        checkParameter
        (
            context, "mu" + n, branches_[a].mu, 0, physicalBounds::modulusMax,
            "Pa"
        );
        checkParameter
        (
            context, "tau" + n, branches_[a].tau, 0, physicalBounds::timeMax,
            "s"
        );
        beta_.push_back(branches_[a].mu/mu0);
    }
}


double solid::Viscoelastic::relaxationFactor(double x)
{
    if (x < 1e-4)
    {
        return 1.0 - x/2.0 + x*x/6.0 - x*x*x/24.0;
    }
    return -std::expm1(-x)/x;
}


void solid::Viscoelastic::initHistory(double* h) const
{
    for (int i = 0; i <= offsetD(); ++i) h[i] = 0;
    base_->initHistory(h + offsetD() + 1);
}


double solid::Viscoelastic::instantaneousShearModulus() const
{
    double mu = base_->instantaneousShearModulus();
    for (const auto& b : branches_) mu += b.mu;
    return mu;
}


void solid::Viscoelastic::evaluate
(
    const Mat3& C,
    double dt,
    const double* hOld,
    double* hNew,
    IsoResponse& r
) const
{
    const int nb = offsetD() + 1;
    base_->evaluate(C, dt, hOld + nb, hNew + nb, r);
    r.CC *= 1.0 + update(dt, hOld, hNew, r);
}


void solid::Viscoelastic::stress
(
    const Mat3& C,
    double dt,
    const double* hOld,
    double* hNew,
    IsoResponse& r
) const
{
    const int nb = offsetD() + 1;
    base_->stress(C, dt, hOld + nb, hNew + nb, r);
    update(dt, hOld, hNew, r);
}


double solid::Viscoelastic::update
(
    double dt,
    const double* hOld,
    double* hNew,
    IsoResponse& r
) const
{
    using namespace tensor;
    const Vec6 Sinf = toVoigt(r.S);
    Vec6 dS;
    for (int i = 0; i < 6; ++i) dS(i) = Sinf(i) - hOld[i];

    double gSum = 0;
    double dissipation = hOld[offsetD()];
    Vec6 Qsum = Vec6::Zero();
    if (!(dt == cacheDt_))
    {
        cacheExp_.resize(branches_.size());
        cacheG_.resize(branches_.size());
        for (std::size_t a = 0; a < branches_.size(); ++a)
        {
            const double x = dt > 0 ? dt/branches_[a].tau : 0.0;
            cacheExp_[a] = std::exp(-x);
            cacheG_[a] = relaxationFactor(x);
        }
        cacheDt_ = dt;
    }
    for (std::size_t a = 0; a < branches_.size(); ++a)
    {
        const double ex = cacheExp_[a];
        const double g = cacheG_[a];
        const double* qo = hOld + offsetQ(a);
        double* qn = hNew + offsetQ(a);
        Vec6 Qo, Qn;
        for (int i = 0; i < 6; ++i)
        {
            Qo(i) = qo[i];
            Qn(i) = ex*qo[i] + g*beta_[a]*dS(i);
            qn[i] = Qn(i);
        }
        Qsum += Qn;
        gSum += g*beta_[a];
        const double mu = branches_[a].mu;
        r.psi += ddot(Qn, Qn)/(4*mu);
        dissipation +=
            dt*0.5*(ddot(Qo, Qo) + ddot(Qn, Qn))/(2*mu*branches_[a].tau);
    }
    for (int i = 0; i < 6; ++i) hNew[i] = Sinf(i);
    hNew[offsetD()] = dissipation;
    r.S += fromVoigt(Qsum);
    return gSum;
}
