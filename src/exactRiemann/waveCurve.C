/*---------------------------------------------------------------------------*\
    Template definitions of riemann::waveCurve (included by waveCurve.H)
\*---------------------------------------------------------------------------*/

#include <algorithm>
#include <cmath>

namespace riemann
{

template<class Eos>
waveCurve<Eos>::waveCurve(const Eos& eos, double rho, double p, double rtol)
:
    rho_(rho),
    p_(p),
    e_(eos.e(rho, p)),
    c_(std::sqrt(eos.c2(rho, e_))),
    hugoniot_(eos, rho, p, e_),
    isentrope_(eos, rho, e_, rtol)
{}


template<class Eos>
typename waveCurve<Eos>::point waveCurve<Eos>::at(double p)
{
    if (p > p_)
    {
        const auto h = hugoniot_.at(p);
        const double dv = 1/rho_ - 1/h.rho;
        const double f = std::sqrt((p - p_)*std::max(dv, 0.0));
        const double dfdp =
            f > 0
          ? (dv - (p - p_)*h.dvdp)/(2*f)
          : 1/(rho_*c_);
        const double dvdpK = -1/(rho_*rho_*c_*c_);
        const double m =
            dv > 1e-6/rho_
          ? std::sqrt((p - p_)/dv)
          : std::sqrt(-2/(dvdpK + h.dvdp));
        return {p, h.rho, h.e, f, dfdp, m, true};
    }
    if (const auto s = isentrope_.atPressure(p))
    {
        return {p, s->rho, s->e, s->w, 1/(s->rho*s->c), 0, true};
    }
    const auto& fl = floor();
    const double slope = 1/(fl.rho*fl.c);
    return {p, fl.rho, fl.e, fl.w + (p - fl.p)*slope, slope, 0, false};
}

} // namespace riemann
