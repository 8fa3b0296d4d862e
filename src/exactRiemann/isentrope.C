/*---------------------------------------------------------------------------*\
    Template definitions of riemann::isentrope (included by isentrope.H)
\*---------------------------------------------------------------------------*/

#include "rootFinders.H"
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace riemann
{

template<class Eos>
isentrope<Eos>::isentrope
(
    const Eos& eos,
    double rhoA,
    double eA,
    double rtol
)
:
    eos_(eos),
    rhoA_(rhoA),
    rtol_(rtol),
    atolE_(0),
    atolW_(0),
    hNext_(-1e-3),
    floorReached_(false),
    floorStatus_(eos::Status::ok)
{
    point a;
    const eos::Status st = evaluate(0, eA, a);
    if (st != eos::Status::ok)
    {
        throw std::invalid_argument
        (
            std::string("isentrope: start state outside the law: ")
          + eos::statusMessage(st)
        );
    }
    a.w = 0;
    nodes_.push_back(a);
    // Absolute tolerances scaled by the start sound speed: e and w start
    // at or near zero for a gauge-pressure law
    atolE_ = rtol_*a.c*a.c;
    atolW_ = rtol_*a.c;
}


template<class Eos>
eos::Status isentrope<Eos>::evaluate(double sigma, double e, point& pt) const
{
    pt.sigma = sigma;
    pt.rho = rhoA_*std::exp(sigma);
    pt.e = e;
    const eos::Status st = eos_.check(pt.rho, e);
    if (st != eos::Status::ok)
    {
        return st;
    }
    const double c2 = eos_.c2(pt.rho, e);
    if (!(c2 > 0))
    {
        return eos::Status::nonPositiveSoundSpeed;
    }
    pt.p = eos_.p(pt.rho, e);
    pt.c = std::sqrt(c2);
    return eos::Status::ok;
}


template<class Eos>
eos::Status isentrope<Eos>::step
(
    const point& a,
    double h,
    point& b,
    double* errNorm
) const
{
    // Dormand & Prince (1980) coefficients
    static constexpr double c2 = 1.0/5, c3 = 3.0/10, c4 = 4.0/5, c5 = 8.0/9;
    static constexpr double
        a21 = 1.0/5,
        a31 = 3.0/40, a32 = 9.0/40,
        a41 = 44.0/45, a42 = -56.0/15, a43 = 32.0/9,
        a51 = 19372.0/6561, a52 = -25360.0/2187, a53 = 64448.0/6561,
        a54 = -212.0/729,
        a61 = 9017.0/3168, a62 = -355.0/33, a63 = 46732.0/5247,
        a64 = 49.0/176, a65 = -5103.0/18656,
        b1 = 35.0/384, b3 = 500.0/1113, b4 = 125.0/192,
        b5 = -2187.0/6784, b6 = 11.0/84;
    // Fifth- minus fourth-order weights
    static constexpr double
        d1 = 71.0/57600, d3 = -71.0/16695, d4 = 71.0/1920,
        d5 = -17253.0/339200, d6 = 22.0/525, d7 = -1.0/40;

    // Right-hand side: de/dsigma = p/rho, dw/dsigma = c
    double ke[7], kw[7];
    point s;
    auto stage = [&](int i, double dSigma, double e)
    {
        const eos::Status st = evaluate(a.sigma + dSigma, e, s);
        if (st == eos::Status::ok)
        {
            ke[i] = s.p/s.rho;
            kw[i] = s.c;
        }
        return st;
    };

    ke[0] = a.p/a.rho;
    kw[0] = a.c;
    eos::Status st;
    if
    (
        (st = stage(1, c2*h, a.e + h*a21*ke[0])) != eos::Status::ok
     || (st = stage(2, c3*h, a.e + h*(a31*ke[0] + a32*ke[1])))
        != eos::Status::ok
     || (
            st = stage
            (
                3, c4*h, a.e + h*(a41*ke[0] + a42*ke[1] + a43*ke[2])
            )
        ) != eos::Status::ok
     || (
            st = stage
            (
                4, c5*h,
                a.e + h*(a51*ke[0] + a52*ke[1] + a53*ke[2] + a54*ke[3])
            )
        ) != eos::Status::ok
     || (
            st = stage
            (
                5, h,
                a.e
              + h*(a61*ke[0] + a62*ke[1] + a63*ke[2] + a64*ke[3]
              + a65*ke[4])
            )
        ) != eos::Status::ok
    )
    {
        return st;
    }

    const double e =
        a.e
      + h*(b1*ke[0] + b3*ke[2] + b4*ke[3] + b5*ke[4] + b6*ke[5]);
    const double w =
        a.w
      + h*(b1*kw[0] + b3*kw[2] + b4*kw[3] + b5*kw[4] + b6*kw[5]);

    // Last stage at the new point (first-same-as-last)
    st = evaluate(a.sigma + h, e, b);
    if (st != eos::Status::ok)
    {
        return st;
    }
    b.w = w;
    ke[6] = b.p/b.rho;
    kw[6] = b.c;

    if (errNorm)
    {
        const double errE =
            h*(d1*ke[0] + d3*ke[2] + d4*ke[3] + d5*ke[4] + d6*ke[5]
          + d7*ke[6]);
        const double errW =
            h*(d1*kw[0] + d3*kw[2] + d4*kw[3] + d5*kw[4] + d6*kw[5]
          + d7*kw[6]);
        *errNorm = std::max
        (
            std::abs(errE)/(atolE_ + rtol_*std::abs(e)),
            std::abs(errW)/(atolW_ + rtol_*std::abs(w))
        );
    }
    return eos::Status::ok;
}


template<class Eos>
bool isentrope<Eos>::extend()
{
    if (floorReached_)
    {
        return false;
    }
    if (nodes_.size() >= maxNodes_)
    {
        throw std::runtime_error
        (
            "isentrope: more than 200000 steps; the law is too stiff for "
            "the integrator"
        );
    }
    const point a = nodes_.back();
    double h = std::max(hNext_, sigmaMin_ - a.sigma);
    eos::Status lastFailure = eos::Status::ok;
    while (true)
    {
        point b;
        double err = 0;
        const eos::Status st = step(a, h, b, &err);
        if (st == eos::Status::ok && err <= 1)
        {
            nodes_.push_back(b);
            steps_.push_back(h);
            const double grow =
                err > 0 ? std::min(5.0, 0.9*std::pow(err, -0.2)) : 5.0;
            hNext_ = std::max(-hMax_, grow*h);
            if (b.sigma <= sigmaMin_)
            {
                floorReached_ = true;
                floorStatus_ = eos::Status::nonPositiveDensity;
            }
            return true;
        }
        if (st != eos::Status::ok)
        {
            lastFailure = st;
            h *= 0.25;
        }
        else
        {
            h *= std::max(0.1, 0.9*std::pow(err, -0.2));
        }
        if (std::abs(h) < hMin_)
        {
            floorReached_ = true;
            floorStatus_ =
                lastFailure == eos::Status::ok
              ? eos::Status::nonPositiveSoundSpeed
              : lastFailure;
            return false;
        }
    }
}


template<class Eos>
template<class G>
typename isentrope<Eos>::point isentrope<Eos>::solveInStep
(
    std::size_t i,
    const G& g,
    double target
) const
{
    const point& a = nodes_[i];
    const double hi = steps_[i];
    auto stepTo = [&](double h)
    {
        point b;
        if (step(a, h, b, nullptr) != eos::Status::ok)
        {
            throw std::logic_error
            (
                "isentrope: a partial step left the domain of the law"
            );
        }
        return b;
    };
    const rootResult r = brent
    (
        [&](double h) { return g(stepTo(h)) - target; },
        0.0, hi,
        g(a) - target, g(nodes_[i + 1]) - target,
        1e-3*std::numeric_limits<double>::epsilon()*std::abs(hi),
        200
    );
    return r.x == hi ? nodes_[i + 1] : stepTo(r.x);
}


template<class Eos>
std::optional<typename isentrope<Eos>::point>
isentrope<Eos>::atPressure(double p)
{
    if (p >= nodes_.front().p)
    {
        return nodes_.front();
    }
    while (nodes_.back().p > p)
    {
        if (!extend())
        {
            return std::nullopt;
        }
    }
    // First node at or below p (pressure decreases along the nodes)
    const auto it = std::lower_bound
    (
        nodes_.begin(), nodes_.end(), p,
        [](const point& n, double v) { return n.p > v; }
    );
    const std::size_t j = it - nodes_.begin();
    if (it->p == p)
    {
        return *it;
    }
    return solveInStep(j - 1, [](const point& n) { return n.p; }, p);
}


template<class Eos>
const typename isentrope<Eos>::point& isentrope<Eos>::floor()
{
    while (extend())
    {}
    return nodes_.back();
}


template<class Eos>
typename isentrope<Eos>::point
isentrope<Eos>::atCharacteristic(double g) const
{
    auto gOf = [](const point& n) { return n.w + n.c; };
    if (g >= gOf(nodes_.front()))
    {
        return nodes_.front();
    }
    for (std::size_t i = 1; i < nodes_.size(); ++i)
    {
        if (!(gOf(nodes_[i]) < gOf(nodes_[i - 1])))
        {
            throw std::runtime_error
            (
                "isentrope: u -+ c is not monotone through the rarefaction "
                "(fundamental derivative <= 0): composite waves of a "
                "non-convex law are not supported"
            );
        }
        if (gOf(nodes_[i]) <= g)
        {
            return solveInStep(i - 1, gOf, g);
        }
    }
    return nodes_.back();
}

} // namespace riemann
