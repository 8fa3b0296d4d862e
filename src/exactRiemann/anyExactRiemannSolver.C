/*---------------------------------------------------------------------------*\
    riemann::anyExactRiemannSolver
\*---------------------------------------------------------------------------*/

#include "anyExactRiemannSolver.H"

namespace riemann
{

namespace
{

using solverVariant = std::variant
<
    exactRiemannSolver<eos::MieGruneisen>,
    exactRiemannSolver<eos::StiffenedGas>,
    exactRiemannSolver<eos::IdealGas>
>;

solverVariant makeSolver
(
    const AnyEos& law,
    const primitiveState& left,
    const primitiveState& right,
    double rtol
)
{
    return std::visit
    (
        [&](const auto& l) -> solverVariant
        {
            using law_t = std::decay_t<decltype(l)>;
            return exactRiemannSolver<law_t>(l, left, right, rtol);
        },
        law
    );
}

} // namespace


anyExactRiemannSolver::anyExactRiemannSolver
(
    const AnyEos& law,
    const primitiveState& left,
    const primitiveState& right,
    double rtol
)
:
    solver_(makeSolver(law, left, right, rtol))
{}


const starState& anyExactRiemannSolver::star() const
{
    return std::visit
    (
        [](const auto& s) -> const starState& { return s.star(); }, solver_
    );
}


const waveStructure& anyExactRiemannSolver::waves() const
{
    return std::visit
    (
        [](const auto& s) -> const waveStructure& { return s.waves(); },
        solver_
    );
}


sampledState anyExactRiemannSolver::sample(double xi) const
{
    return std::visit([xi](const auto& s) { return s.sample(xi); }, solver_);
}


std::vector<sampledState> anyExactRiemannSolver::sample
(
    const std::vector<double>& x,
    double t,
    double x0
) const
{
    return std::visit
    (
        [&](const auto& s) { return s.sample(x, t, x0); }, solver_
    );
}

} // namespace riemann
