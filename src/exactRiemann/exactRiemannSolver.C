/*---------------------------------------------------------------------------*\
    Template definitions of riemann::exactRiemannSolver (included by
    exactRiemannSolver.H)
\*---------------------------------------------------------------------------*/

#include "domainError.H"
#include "rootFinders.H"
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace riemann
{

namespace detail
{

//- The state, after checking that it lies inside the law
template<class Eos>
const primitiveState& checkedState
(
    const Eos& eos,
    const primitiveState& s,
    const char* side
)
{
    const std::string where = std::string(side) + " initial state";
    if (!std::isfinite(s.u) || !std::isfinite(s.p))
    {
        throw domainError
        (
            where, eos::Status::nonFiniteEnergy,
            "velocity and pressure must be finite"
        );
    }
    const eos::Status st =
        std::isfinite(s.rho) && s.rho > 0
      ? eos.check(s.rho, eos.e(s.rho, s.p))
      : eos::Status::nonPositiveDensity;
    if (st != eos::Status::ok)
    {
        std::ostringstream os;
        os  << "rho = " << s.rho << " kg/m^3, p = " << s.p << " Pa";
        throw domainError(where, st, os.str());
    }
    return s;
}

} // namespace detail


template<class Eos>
exactRiemannSolver<Eos>::exactRiemannSolver
(
    const Eos& eos,
    const primitiveState& left,
    const primitiveState& right,
    double rtol
)
:
    eos_(eos),
    left_(detail::checkedState(eos, left, "left")),
    right_(detail::checkedState(eos, right, "right")),
    curveL_(eos, left.rho, left.p, rtol),
    curveR_(eos, right.rho, right.p, rtol),
    star_(),
    waves_()
{
    solve();
}


template<class Eos>
void exactRiemannSolver<Eos>::solve()
{
    const double du = right_.u - left_.u;
    const double zL = curveL_.rho()*curveL_.c();
    const double zR = curveR_.rho()*curveR_.c();

    auto fdf = [&](double p)
    {
        const auto l = curveL_.at(p);
        const auto r = curveR_.at(p);
        return std::make_pair(l.f + r.f + du, l.dfdp + r.dfdp);
    };

    const double p0 =
        (zR*left_.p + zL*right_.p - zL*zR*du)/(zL + zR);
    const double pScale = std::max
    (
        {
            std::abs(left_.p), std::abs(right_.p),
            zL*std::abs(du), zR*std::abs(du),
            std::numeric_limits<double>::min()
        }
    );
    // |f| tolerance far above its rounding eps (|f_L| + |f_R| + |du|)
    const double fTol =
        1e-12*(curveL_.c() + curveR_.c() + std::abs(du));
    const double inf = std::numeric_limits<double>::infinity();
    const rootResult r =
        safeguardedNewton(fdf, p0, -inf, inf, 2e-15*pScale, fTol, 100);
    if (!r.converged)
    {
        throw std::runtime_error
        (
            "exactRiemannSolver: star pressure not converged in 100 "
            "iterations, last p = " + std::to_string(r.x) + " Pa"
        );
    }

    const double pStar = r.x;
    const auto l = curveL_.at(pStar);
    const auto rr = curveR_.at(pStar);

    // A rarefaction that would have to pass its floor: no solution inside
    // the law
    auto reportFloor = [&](waveCurve<Eos>& curve, const char* side)
    {
        const auto& fl = curve.floor();
        std::ostringstream os;
        os  << "uR - uL = " << du << " m/s needs more expansion than the "
            << "rarefactions supply inside the law: the " << side
            << " one ends at p = " << fl.p << " Pa, rho = " << fl.rho
            << " kg/m^3 after a velocity jump of " << -fl.w << " m/s";
        throw domainError
        (
            std::string(side) + " rarefaction", curve.floorStatus(),
            os.str()
        );
    };
    if (!l.reachable) reportFloor(curveL_, "left");
    if (!rr.reachable) reportFloor(curveR_, "right");

    const double uStar = 0.5*(left_.u + right_.u) + 0.5*(rr.f - l.f);
    star_ = {pStar, uStar, l.rho, rr.rho, l.e, rr.e, r.iterations};

    waves_.contactSpeed = uStar;
    if (pStar > left_.p)
    {
        const double s = left_.u - l.massFlux/left_.rho;
        waves_.left = {waveType::shock, s, s};
    }
    else
    {
        waves_.left =
        {
            waveType::rarefaction,
            left_.u - curveL_.c(),
            uStar - std::sqrt(eos_.c2(l.rho, l.e))
        };
    }
    if (pStar > right_.p)
    {
        const double s = right_.u + rr.massFlux/right_.rho;
        waves_.right = {waveType::shock, s, s};
    }
    else
    {
        waves_.right =
        {
            waveType::rarefaction,
            right_.u + curveR_.c(),
            uStar + std::sqrt(eos_.c2(rr.rho, rr.e))
        };
    }
}


template<class Eos>
sampledState exactRiemannSolver<Eos>::sample(double xi) const
{
    if (xi <= star_.u)
    {
        const wave& w = waves_.left;
        const sampledState outer
        {
            left_.rho, left_.u, left_.p, curveL_.e()
        };
        if (xi < w.headSpeed)
        {
            return outer;
        }
        if (w.type == waveType::shock || xi >= w.tailSpeed)
        {
            return {star_.rhoL, star_.u, star_.p, star_.eL};
        }
        const auto s = curveL_.fan().atCharacteristic(left_.u - xi);
        return {s.rho, left_.u - s.w, s.p, s.e};
    }

    const wave& w = waves_.right;
    const sampledState outer
    {
        right_.rho, right_.u, right_.p, curveR_.e()
    };
    if (xi > w.headSpeed)
    {
        return outer;
    }
    if (w.type == waveType::shock || xi <= w.tailSpeed)
    {
        return {star_.rhoR, star_.u, star_.p, star_.eR};
    }
    const auto s = curveR_.fan().atCharacteristic(xi - right_.u);
    return {s.rho, right_.u + s.w, s.p, s.e};
}


template<class Eos>
std::vector<sampledState> exactRiemannSolver<Eos>::sample
(
    const std::vector<double>& x,
    double t,
    double x0
) const
{
    if (!(t > 0) || !std::isfinite(t))
    {
        throw std::invalid_argument
        (
            "exactRiemannSolver::sample: time t = " + std::to_string(t)
          + " s must be finite and > 0"
        );
    }
    std::vector<sampledState> states;
    states.reserve(x.size());
    for (const double xj : x)
    {
        states.push_back(sample((xj - x0)/t));
    }
    return states;
}

} // namespace riemann
