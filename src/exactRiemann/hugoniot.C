/*---------------------------------------------------------------------------*\
    Template definitions of riemann::hugoniot (included by hugoniot.H)
\*---------------------------------------------------------------------------*/

#include "domainError.H"
#include "rootFinders.H"
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace riemann
{

template<class Eos>
hugoniot<Eos>::hugoniot(const Eos& eos, double rhoA, double pA, double eA)
:
    eos_(eos),
    rhoA_(rhoA),
    pA_(pA),
    eA_(eA)
{}


template<class Eos>
double hugoniot<Eos>::residual(double v, double p) const
{
    return eos_.e(1/v, p) - eA_ - 0.5*(p + pA_)*(1/rhoA_ - v);
}


template<class Eos>
typename hugoniot<Eos>::point hugoniot<Eos>::at(double p) const
{
    const double vA = 1/rhoA_;
    if (p <= pA_)
    {
        const double c2 = eos_.c2(rhoA_, eA_);
        return {rhoA_, eA_, -vA*vA/c2, 0};
    }

    // Lower end of the bracket: H(vLo) < 0 with a state inside the law
    auto valid = [&](double v)
    {
        return eos_.check(1/v, eos_.e(1/v, p)) == eos::Status::ok;
    };
    double vHi = vA;
    double vBad = 0;
    double vLo = 0.5*vA;
    eos::Status lastStatus = eos::Status::ok;
    bool found = false;
    for (int k = 0; k < 400 && !found; ++k)
    {
        if (valid(vLo))
        {
            if (residual(vLo, p) < 0)
            {
                found = true;
            }
            else
            {
                vHi = vLo;
                vLo = 0.5*(vLo + vBad);
            }
        }
        else
        {
            lastStatus = eos_.check(1/vLo, eos_.e(1/vLo, p));
            vBad = vLo;
            vLo = 0.5*(vLo + vHi);
        }
    }
    if (!found)
    {
        throw domainError
        (
            "shock", lastStatus,
            "no post-shock state on the Hugoniot at p = "
          + std::to_string(p) + " Pa"
        );
    }

    auto dpde = [&](double v) { return eos_.dpde(1/v, eos_.e(1/v, p)); };
    auto fdf = [&](double v)
    {
        const double rho = 1/v;
        const double e = eos_.e(rho, p);
        return std::make_pair
        (
            residual(v, p),
            eos_.dpdrho(rho, e)/(eos_.dpde(rho, e)*v*v) + 0.5*(p + pA_)
        );
    };

    // Acoustic first guess dv = -dp/(rho c)^2, kept inside the bracket
    const double zA2 = rhoA_*rhoA_*eos_.c2(rhoA_, eA_);
    double v0 = vA - (p - pA_)/zA2;
    if (!(v0 > vLo && v0 < vHi)) v0 = 0.5*(vLo + vHi);

    // |H| tolerance far above its rounding eps (|e| + p v)
    const double hTol =
        1e-10*(std::abs(eA_) + (std::abs(p) + std::abs(pA_))*vA);
    const rootResult r = safeguardedNewton
    (
        fdf, v0, vLo, vHi,
        4*std::numeric_limits<double>::epsilon()*vA, hTol, 200
    );
    const double v = r.x;
    const double dHdv = fdf(v).second;
    const double dHdp = 1/dpde(v) - 0.5*(vA - v);
    return {1/v, eos_.e(1/v, p), -dHdp/dHdv, r.iterations};
}

} // namespace riemann
