/*---------------------------------------------------------------------------*\
Description
    Unit tests of the FSI coupling schemes (src/fsi/couplingSchemes) on
    linear fixed-point problems x = A x + b, the model of one coupled time
    step: x the interface velocity, A x + b the solid's answer x~ to it.
    Every scheme must reach the known solution (I - A)^-1 b; the iteration
    counts are gold values (gold/couplingScheme.dat). Also: Aitken's
    relaxation factors against Kuettler & Wall's formula, the finite
    termination of IQN-ILS on a linear map, Robin's documented update and
    its one-iteration convergence for an acoustic fluid response, the
    restart statistics, the errors of bad dictionaries and the Usage
    examples of the headers.

\*---------------------------------------------------------------------------*/

#include "couplingScheme.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "foamTestCase.H"
#include "goldFile.H"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <cmath>
#include <set>
#include <string>

using namespace Foam;

namespace
{

//- x = A x + b with its exact solution
struct linearProblem
{
    Eigen::MatrixXd A;
    Eigen::VectorXd b;

    Eigen::VectorXd solution() const
    {
        const label n = b.size();
        return (Eigen::MatrixXd::Identity(n, n) - A).partialPivLu().solve(b);
    }

    scalarField answer(const scalarField& x) const
    {
        scalarField xTilde(x.size());
        const Eigen::VectorXd y =
            A*Eigen::Map<const Eigen::VectorXd>(x.cdata(), x.size()) + b;
        forAll(xTilde, i) xTilde[i] = y(i);
        return xTilde;
    }
};

//- Symmetric A = Q diag(lambda) Q^T, Q orthogonal from a fixed matrix (no
//  random generator: the same problem on every platform); b of order 1
linearProblem symmetricProblem(const std::vector<scalar>& lambda)
{
    const label n = label(lambda.size());
    Eigen::MatrixXd M(n, n);
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            M(i, j) = std::sin(1.0 + 7.0*i + 3.0*j*j);
        }
    }
    const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(M)
        .householderQ();
    Eigen::VectorXd L(n), b(n);
    for (label i = 0; i < n; ++i)
    {
        L(i) = lambda[i];
        b(i) = 1.0 + 0.5*std::cos(2.0*i);
    }
    return {Q*L.asDiagonal()*Q.transpose(), b};
}

//- Coupling dictionary named as in a case, so that error messages can be
//  checked for the file
dictionary couplingDict(const std::string& entries)
{
    IStringStream is(entries);
    dictionary dict(is);
    dict.name() = "constant/fsiProperties/coupling";
    return dict;
}

dictionary schemeDict(const word& scheme, const std::string& extra = "")
{
    return couplingDict
    (
        "scheme " + scheme + "; maxIter 500; tolerance 1e-10;"
        " velocityScale 1e-12; onNonConvergence stop;"
        " initialRelaxation 0.1; " + extra
    );
}

//- One time step of the scheme on the problem from x (replaced by the last
//  iterate); the number of fluid-solid passes
label solveStep
(
    couplingScheme& scheme,
    const linearProblem& problem,
    scalarField& x,
    const scalarField& beta
)
{
    scheme.beginStep();
    bool done = false;
    while (!done)
    {
        done = scheme.update(x, problem.answer(x), beta);
    }
    scheme.endStep(0);
    return scheme.iterations();
}

scalar maxError(const scalarField& x, const Eigen::VectorXd& xStar)
{
    scalar e = 0;
    forAll(x, i) e = max(e, mag(x[i] - xStar(i)));
    return e;
}

//- The error bound of a converged step: |r| <= tol |x~| and
//  x - x* = (A - I)^-1 r
scalar errorBound(const linearProblem& p, const scalar tol)
{
    const label n = p.b.size();
    const Eigen::MatrixXd inv =
        (p.A - Eigen::MatrixXd::Identity(n, n)).inverse();
    const Eigen::VectorXd xStar = p.solution();
    return inv.cwiseAbs().rowwise().sum().maxCoeff()
       *tol*xStar.cwiseAbs().maxCoeff()*1.01;
}

const foamUnit::goldFile& gold()
{
    static const foamUnit::goldFile g("couplingScheme");
    return g;
}

//- The passes of a step from x whose answer is xTilde whatever x is
//  (converged at the second pass), before endStep
void endWith
(
    couplingScheme& scheme,
    const scalarField& x,
    const scalarField& xTilde
)
{
    scalarField xs(x);
    while (!scheme.update(xs, xTilde, scalarField(x.size(), Zero))) {}
    ASSERT_TRUE(scheme.converged());
}

//- A field of the given values
scalarField values(std::initializer_list<scalar> list)
{
    return scalarField(List<scalar>(list));
}

//- An added-mass-like map: eigenvalues of both signs, one below -1 (the
//  plain fixed-point iteration diverges)
const std::vector<scalar> lambda6{-2.5, -1.2, -0.6, 0.2, 0.5, 0.8};

} // End anonymous namespace


TEST(couplingScheme, implicitSchemesReachTheSolution)
{
    const linearProblem p = symmetricProblem(lambda6);
    const Eigen::VectorXd xStar = p.solution();
    const scalarField beta(6, 1.0);
    for (const word name : {"aitken", "IQNILS", "robin"})
    {
        SCOPED_TRACE(name);
        autoPtr<couplingScheme> scheme(couplingScheme::New(schemeDict(name)));
        EXPECT_TRUE(scheme->iterative());
        scalarField x(6, Zero);
        const label n = solveStep(scheme(), p, x, beta);
        EXPECT_TRUE(scheme->converged());
        EXPECT_LE(scheme->residual(), 1e-10);
        EXPECT_LE(maxError(x, xStar), errorBound(p, 1e-10));
        gold().check(name + ".linear6.iterations", n);
    }
}


TEST(couplingScheme, explicitStaggeredIsOnePassAndIteratesOverSteps)
{
    // One pass per step, x untouched: over the steps the interface
    // velocity follows the plain fixed-point iteration, which converges for
    // a contraction (weak coupling)
    const linearProblem p = symmetricProblem({-0.7, -0.3, 0.1, 0.4, 0.6, 0.7});
    const Eigen::VectorXd xStar = p.solution();
    autoPtr<couplingScheme> scheme
    (
        couplingScheme::New(schemeDict("explicitStaggered"))
    );
    EXPECT_FALSE(scheme->iterative());
    scalarField x(6, Zero);
    label nSteps = 0;
    while (maxError(x, xStar) > 1e-10*max(mag(xStar.maxCoeff()), 1.0))
    {
        ASSERT_LT(nSteps, 1000) << "no convergence over the steps";
        const scalarField xTilde(p.answer(x));
        const scalarField xBefore(x);
        scheme->beginStep();
        ASSERT_TRUE(scheme->update(x, xTilde, scalarField(6, Zero)));
        EXPECT_EQ(x, xBefore) << "explicitStaggered changed x";
        EXPECT_TRUE(scheme->converged());
        EXPECT_DOUBLE_EQ
        (
            scheme->residual(),
            max(mag(xTilde - x))/max(max(mag(xTilde)), 1e-12)
        );
        scheme->endStep(nSteps);
        x = xTilde;
        ++nSteps;
    }
    EXPECT_EQ(scheme->nSteps(), nSteps);
    EXPECT_EQ(scheme->nIterations(), nSteps);
    EXPECT_EQ(scheme->nNonConverged(), 0);
    gold().check("explicitStaggered.contraction6.steps", nSteps);
}


TEST(couplingScheme, aitkenRelaxationFactorsFollowTheFormula)
{
    // w_1 = w_0, w_k = -w_k-1 r_k-1.(r_k - r_k-1)/|r_k - r_k-1|^2; observed
    // as w_k = (x_k+1 - x_k).r_k/|r_k|^2, while |r| is large enough against
    // x for the observation (a difference of iterates) to hold 10 digits
    const linearProblem p = symmetricProblem(lambda6);
    autoPtr<couplingScheme> scheme(couplingScheme::New(schemeDict("aitken")));
    scalarField x(6, Zero);
    scalarField rPrev;
    scalar omega = 0.1;
    label nChecked = 0;
    scheme->beginStep();
    for (bool done = false; !done; )
    {
        const scalarField xTilde(p.answer(x));
        const scalarField r(xTilde - x);
        const scalarField xOld(x);
        done = scheme->update(x, xTilde, scalarField(6, Zero));
        if (done) break;
        if (rPrev.size())
        {
            const scalarField dr(r - rPrev);
            omega = -omega*sum(rPrev*dr)/sumSqr(dr);
        }
        rPrev = r;
        if (max(mag(r)) < 1e-5*max(mag(xTilde)))
        {
            continue;
        }
        const scalar observed = sum((x - xOld)*r)/sumSqr(r);
        EXPECT_NEAR(observed, omega, 1e-10*mag(omega))
            << "iteration " << scheme->iterations();
        ++nChecked;
    }
    scheme->endStep(0);
    EXPECT_GE(nChecked, 10);
}


TEST(couplingScheme, aitkenIsExactSecantOnAScalarMap)
{
    // On x = a x + b the second Aitken factor is 1/(1 - a): the third pass
    // meets the solution, even for a < -1 (plain iteration diverges)
    linearProblem p;
    p.A = Eigen::MatrixXd::Constant(1, 1, -4.0);
    p.b = Eigen::VectorXd::Constant(1, 2.0);
    autoPtr<couplingScheme> scheme(couplingScheme::New(schemeDict("aitken")));
    scalarField x(1, Zero);
    const label n = solveStep(scheme(), p, x, scalarField(1, Zero));
    EXPECT_NEAR(x[0], 0.4, 1e-12);
    gold().check("aitken.scalar.iterations", n);
}


TEST(couplingScheme, IQNILSTerminatesOnALinearMap)
{
    // The least-squares model is exact once its columns span the space:
    // n distinct eigenvalues, at most n + 1 updates after the first pass
    // (n + 2 passes); with m distinct eigenvalues, m + 2 passes (as GMRES)
    for (const auto& lambda : {lambda6, {-2.5, -2.5, -2.5, 0.5, 0.5, 0.5}})
    {
        std::set<scalar> distinct(lambda.begin(), lambda.end());
        const label m = label(distinct.size());
        SCOPED_TRACE(m);
        const linearProblem p = symmetricProblem(lambda);
        autoPtr<couplingScheme> scheme
        (
            couplingScheme::New(schemeDict("IQNILS"))
        );
        scalarField x(6, Zero);
        const label n = solveStep(scheme(), p, x, scalarField(6, Zero));
        EXPECT_LE(n, m + 2);
        EXPECT_LE(maxError(x, p.solution()), errorBound(p, 1e-10));
        gold().check
        (
            "IQNILS.distinct" + std::to_string(m) + ".iterations", n
        );
    }
}


TEST(couplingScheme, IQNILSReusedColumnsSolveTheNextStepAtOnce)
{
    // The same linear map in the next step: with the columns of one earlier
    // step (reuse 1) the first update is exact, the second pass converges;
    // without (reuse 0) the step starts again from a relaxation
    const linearProblem p1 = symmetricProblem(lambda6);
    linearProblem p2 = p1;
    p2.b = -0.3*p1.b + Eigen::VectorXd::LinSpaced(6, 0.0, 1.0);
    for (const label reuse : {0, 1})
    {
        SCOPED_TRACE(reuse);
        autoPtr<couplingScheme> scheme
        (
            couplingScheme::New
            (
                schemeDict("IQNILS", "reuse " + std::to_string(reuse) + ";")
            )
        );
        scalarField x(6, Zero);
        solveStep(scheme(), p1, x, scalarField(6, Zero));
        const label n2 = solveStep(scheme(), p2, x, scalarField(6, Zero));
        EXPECT_LE(maxError(x, p2.solution()), errorBound(p2, 1e-10));
        gold().check
        (
            "IQNILS.reuse" + std::to_string(reuse) + ".step2.iterations", n2
        );
    }
}


TEST(couplingScheme, robinUpdateIsTheDocumentedFormula)
{
    // x_k+1 = (x~_k + beta x_k)/(1 + beta), per dof
    autoPtr<couplingScheme> scheme(couplingScheme::New(schemeDict("robin")));
    const scalarField beta(scalarList({0, 0.3, 1, 4, 25, 1e3}));
    scalarField x(scalarList({0.1, -0.2, 0.3, 1, -2, 5}));
    const scalarField xTilde(scalarList({1, 2, -3, 0.5, 0.25, -1}));
    const scalarField xOld(x);
    scheme->beginStep();
    ASSERT_FALSE(scheme->update(x, xTilde, beta));
    forAll(x, i)
    {
        const scalar expected = (xTilde[i] + beta[i]*xOld[i])/(1 + beta[i]);
        EXPECT_NEAR(x[i], expected, 1e-15*max(mag(expected), 1.0)) << i;
    }
}


TEST(couplingScheme, robinRemovesAnAcousticErrorInOneIteration)
{
    // Solid answer to a fluid whose wall force is the acoustic one:
    // x~ = b - beta x (beta the added damping ratio). The Robin update is
    // then exact: the second pass converges, for every impedance ratio
    const scalarField beta(scalarList({0.05, 0.5, 1, 3, 10, 100}));
    linearProblem p;
    const Eigen::VectorXd minusBeta =
        -Eigen::Map<const Eigen::VectorXd>(beta.cdata(), 6);
    p.A = minusBeta.asDiagonal();
    p.b = Eigen::VectorXd::LinSpaced(6, 1.0, 2.0);
    autoPtr<couplingScheme> scheme(couplingScheme::New(schemeDict("robin")));
    scalarField x(6, Zero);
    const label n = solveStep(scheme(), p, x, beta);
    EXPECT_LE(maxError(x, p.solution()), errorBound(p, 1e-10));
    gold().check("robin.acoustic.iterations", n);
}


TEST(couplingScheme, nonConvergedStepIsCountedOrStops)
{
    const linearProblem p = symmetricProblem(lambda6);
    {
        autoPtr<couplingScheme> scheme
        (
            couplingScheme::New
            (
                couplingDict
                (
                    "scheme aitken; maxIter 3; tolerance 1e-10;"
                    " onNonConvergence warn;"
                )
            )
        );
        scalarField x(6, Zero);
        EXPECT_EQ(solveStep(scheme(), p, x, scalarField(6, Zero)), 3);
        EXPECT_FALSE(scheme->converged());
        EXPECT_EQ(scheme->nNonConverged(), 1);
    }
    {
        autoPtr<couplingScheme> scheme
        (
            couplingScheme::New
            (
                couplingDict
                (
                    "scheme aitken; maxIter 3; tolerance 1e-10;"
                    " onNonConvergence stop;"
                )
            )
        );
        scalarField x(6, Zero);
        try
        {
            solveStep(scheme(), p, x, scalarField(6, Zero));
            ADD_FAILURE() << "a non-converged step with stop was accepted";
        }
        catch (const Foam::error& err)
        {
            EXPECT_NE(err.message().find("did not converge"), std::string::npos)
                << err.message();
        }
    }
}


TEST(couplingScheme, stateRoundTrip)
{
    // Statistics of steps written at a write time and read at a restart
    const linearProblem p = symmetricProblem(lambda6);
    const dictionary dict
    (
        couplingDict
        (
            "scheme IQNILS; maxIter 5; tolerance 1e-10;"
            " onNonConvergence warn;"
        )
    );
    autoPtr<couplingScheme> a(couplingScheme::New(dict));
    scalarField x(6, Zero);
    for (label step = 0; step < 3; ++step)
    {
        solveStep(a(), p, x, scalarField(6, Zero));
    }
    solveStep(a(), symmetricProblem({0.1, 0.1, 0.1, 0.1, 0.1, 0.1}), x,
        scalarField(6, Zero));
    ASSERT_GT(a->nNonConverged(), 0);

    OStringStream os;
    a->writeState(os);
    IStringStream is(os.str());
    const dictionary state(is);

    autoPtr<couplingScheme> b(couplingScheme::New(dict));
    b->readState(state);
    EXPECT_EQ(b->nSteps(), a->nSteps());
    EXPECT_EQ(b->nIterations(), a->nIterations());
    EXPECT_EQ(b->nNonConverged(), a->nNonConverged());
    OStringStream ra, rb;
    a->report(ra);
    b->report(rb);
    EXPECT_EQ(ra.str(), rb.str());
}


TEST(couplingScheme, predictorsOnALinearAcceleration)
{
    // A solid whose interface acceleration is linear in time, a(t) = a +
    // b t, with unequal steps: the answer of a step is x~ = v_n + dt/4
    // (a_n + a_n+1). centralDifference misses it by dt/4 (a_n+1 - a_n)
    // at every step; extrapolated by that at the first step (no history)
    // and hits it to round-off from the second
    const scalarField a = values({2.0e6, -1.0e6, 5.0e5});
    const scalarField b = values({3.0e15, 1.0e15, -2.0e15});
    const scalarField dts = values({4.0e-11, 3.0e-11, 5.0e-11, 2.5e-11});
    for (const word predictor : {"centralDifference", "extrapolated"})
    {
        SCOPED_TRACE(predictor);
        autoPtr<couplingScheme> scheme
        (
            couplingScheme::New
            (
                schemeDict("robin", "predictor " + predictor + ";")
            )
        );
        EXPECT_EQ(scheme->extrapolated(), predictor == "extrapolated");
        scalar t = 1e-9;
        scalarField v = values({1.0, -2.0, 0.5});
        forAll(dts, step)
        {
            const scalar dt = dts[step];
            const scalarField an(a + b*t);
            const scalarField an1(a + b*(t + dt));
            const scalarField xTilde(v + 0.25*dt*(an + an1));
            scheme->beginStep();
            const scalarField x(scheme->predict(v, an, dt));
            if (predictor == "centralDifference" || step == 0)
            {
                // bitwise the former solver expression
                EXPECT_EQ(x, scalarField(v + 0.5*dt*an));
                EXPECT_LT(max(mag(x - xTilde - 0.25*dt*(an - an1))), 1e-12);
            }
            else
            {
                // to round-off, where central difference misses by
                // dt/4 (a_n+1 - a_n), 4.7e-7 m/s or more here
                EXPECT_LT(max(mag(x - xTilde)), 1e-12*max(mag(xTilde)));
                EXPECT_GT(max(mag(0.25*dt*(an1 - an))), 4e-7);
            }
            endWith(scheme(), x, xTilde);
            scheme->endStep(t);
            v += 0.5*dt*(an + an1);
            t += dt;
        }
    }
}


TEST(couplingScheme, predictorHistoryRoundTrip)
{
    // The extrapolated predictor's history is restart state: the scheme
    // read back predicts the same bits; a centralDifference state has none
    // (the first step after it takes central difference)
    const dictionary dict(schemeDict("robin", "predictor extrapolated;"));
    autoPtr<couplingScheme> a(couplingScheme::New(dict));
    const scalarField v = values({0.3, -0.2});
    const scalarField a0 = values({1.0e6, 2.0e6});
    const scalarField a1 = values({1.5e6, 1.0e6});
    a->beginStep();
    endWith(a(), a->predict(v, a0, 3e-11), v);
    a->endStep(0);
    OStringStream os;
    a->writeState(os);
    IStringStream is(os.str());
    const dictionary state(is);
    EXPECT_TRUE(state.found("previousAcceleration"));

    autoPtr<couplingScheme> b(couplingScheme::New(dict));
    b->readState(state);
    a->beginStep();
    b->beginStep();
    const scalarField xa(a->predict(v, a1, 4e-11));
    const scalarField xb(b->predict(v, a1, 4e-11));
    EXPECT_EQ(xa, xb);
    EXPECT_NE(xa, scalarField(v + 0.5*4e-11*a1));

    autoPtr<couplingScheme> c(couplingScheme::New(schemeDict("robin")));
    c->beginStep();
    endWith(c(), c->predict(v, a0, 3e-11), v);
    c->endStep(0);
    OStringStream oc;
    c->writeState(oc);
    EXPECT_EQ(oc.str().find("previousAcceleration"), std::string::npos);
    IStringStream ic(oc.str());
    autoPtr<couplingScheme> d(couplingScheme::New(dict));
    d->readState(dictionary(ic));
    d->beginStep();
    EXPECT_EQ
    (
        scalarField(d->predict(v, a1, 4e-11)), scalarField(v + 0.5*4e-11*a1)
    );

    // A history of another interface (restart state of another mesh) or
    // a bad time step
    autoPtr<couplingScheme> e(couplingScheme::New(dict));
    e->readState(state);
    e->beginStep();
    try
    {
        e->predict(scalarField(3, Zero), scalarField(3, Zero), 1e-11);
        ADD_FAILURE() << "3 dofs accepted for a history of 2";
    }
    catch (const Foam::error& err)
    {
        EXPECT_NE(err.message().find("have 2 values, the interface 3"),
            std::string::npos) << err.message();
    }
    try
    {
        e->readState
        (
            couplingDict
            (
                "couplingStatistics (1 1 1 0); previousAcceleration"
                " 2(1 2); previousDeltaT 0;"
            )
        );
        ADD_FAILURE() << "previousDeltaT 0 accepted";
    }
    catch (const Foam::IOerror& err)
    {
        EXPECT_NE(err.message().find("previousDeltaT must be > 0 s"),
            std::string::npos) << err.message();
    }

    // The history lost (adv49b i11, fix19f): a state of the extrapolated
    // predictor after a step without its two entries, or with one, is
    // refused naming them (was: taken as no history without a word; one
    // entry: OpenFOAM's "Entry 'previousDeltaT' not found")
    EXPECT_EQ(state.get<word>("predictor"), word("extrapolated")) << os.str();
    {
        IStringStream icd(oc.str());
        EXPECT_EQ(dictionary(icd).get<word>("predictor"),
            word("centralDifference")) << oc.str();
    }
    for
    (
        const auto& c
      : std::vector<std::pair<std::string, std::string>>
        {
            {"couplingStatistics (1 1 1 0); predictor extrapolated;",
             "entries 'previousAcceleration' and 'previousDeltaT' are "
             "missing: the state was written with predictor extrapolated "
             "after 1 steps"},
            {"couplingStatistics (1 1 1 0); predictor extrapolated; "
             "previousAcceleration 2(1 2);",
             "entry 'previousDeltaT' is missing beside entry "
             "'previousAcceleration'"},
            {"couplingStatistics (1 1 1 0); previousDeltaT 1e-11;",
             "entry 'previousAcceleration' is missing beside entry "
             "'previousDeltaT'"}
        }
    )
    {
        autoPtr<couplingScheme> f(couplingScheme::New(dict));
        try
        {
            f->readState(couplingDict(c.first));
            ADD_FAILURE() << c.first << ": accepted";
        }
        catch (const Foam::IOerror& err)
        {
            EXPECT_NE(err.message().find(c.second), std::string::npos)
                << c.first << ": " << err.message();
        }
    }
    // a state without the predictor's name (an earlier build) or of
    // centralDifference: no history, said, and the run goes on
    autoPtr<couplingScheme> g(couplingScheme::New(dict));
    g->readState(couplingDict("couplingStatistics (1 1 1 0);"));
    g->beginStep();
    EXPECT_EQ
    (
        scalarField(g->predict(v, a1, 4e-11)), scalarField(v + 0.5*4e-11*a1)
    );
}


TEST(couplingScheme, badDictionariesNameTheEntry)
{
    struct badCase
    {
        std::string entries;
        std::vector<std::string> message;
    };
    const std::vector<badCase> cases
    {
        {
            "scheme secant;",
            {"secant", "IQNILS", "aitken", "explicitStaggered", "robin"}
        },
        {
            "scheme aitken; tolerance -1e-6;",
            {"entry 'tolerance' = -1e-06", "(0, 0.1]"}
        },
        {
            // a relative residual: 1e3 made every first pass converge
            // (issue 19)
            "scheme IQNILS; tolerance 1e3;",
            {"entry 'tolerance' = 1000", "(0, 0.1]"}
        },
        {
            "scheme robin; velocityScale 0;",
            {"entry 'velocityScale' = 0 m/s", "(0, inf)"}
        },
        {"scheme robin; maxIter 0;", {"entry 'maxIter' = 0", "[1, inf)"}},
        {"scheme robin; onNonConvergence maybe;", {"maybe", "(warn stop)"}},
        {
            "scheme aitken; initialRelaxation 1.5;",
            {"entry 'initialRelaxation' = 1.5", "(0, 1]"}
        },
        {
            "scheme IQNILS; initialRelaxation 0;",
            {"entry 'initialRelaxation' = 0", "(0, 1]"}
        },
        {"scheme IQNILS; reuse -1;", {"entry 'reuse' = -1", "[0, inf)"}},
        {
            "scheme robin; predictor quadratic;",
            {"quadratic", "(centralDifference extrapolated)"}
        },
        {
            "scheme explicitStaggered; predictor extrapolated;",
            {"predictor extrapolated needs an iterative scheme"}
        }
    };
    for (const badCase& c : cases)
    {
        SCOPED_TRACE(c.entries);
        try
        {
            couplingScheme::New(couplingDict(c.entries));
            ADD_FAILURE() << "accepted";
        }
        catch (const Foam::IOerror& err)
        {
            EXPECT_EQ(err.ioFileName(), "constant/fsiProperties/coupling");
            for (const std::string& m : c.message)
            {
                EXPECT_NE(err.message().find(m), std::string::npos)
                    << "no '" << m << "' in: " << err.message();
            }
        }
    }

    // A restart file with a wrong statistics entry
    autoPtr<couplingScheme> s(couplingScheme::New(schemeDict("robin")));
    try
    {
        s->readState(couplingDict("couplingStatistics (1 2 3);"));
        ADD_FAILURE() << "3 statistics accepted";
    }
    catch (const Foam::IOerror& err)
    {
        EXPECT_NE(err.message().find("couplingStatistics needs 4 values"),
            std::string::npos) << err.message();
    }
}


TEST(couplingScheme, usageExamplesAreValidInputs)
{
    // The Usage example of every scheme's header selects that scheme
    struct example
    {
        fileName header;
        word scheme;
    };
    const fileName dir("src/fsi/couplingSchemes");
    for
    (
        const example& ex :
        {
            example{dir/"couplingScheme/couplingScheme.H", "IQNILS"},
            example
            {
                dir/"explicitStaggered/explicitStaggered.H",
                "explicitStaggered"
            },
            example{dir/"aitken/aitken.H", "aitken"},
            example{dir/"IQNILS/IQNILS.H", "IQNILS"},
            example{dir/"robin/robin.H", "robin"}
        }
    )
    {
        SCOPED_TRACE(ex.header);
        IStringStream is(foamUnit::testCase::usageExample(ex.header));
        const dictionary usage(is);
        const dictionary& dict =
            usage.found("coupling") ? usage.subDict("coupling") : usage;
        autoPtr<couplingScheme> scheme(couplingScheme::New(dict));
        EXPECT_EQ(scheme->type(), ex.scheme);
    }
}
