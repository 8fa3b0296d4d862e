// The explicit solver with its elements shared over parts (solid::Partition,
// Model::setPartition; the FSI solver's ranks): the parts' partial element
// forces sum to the serial ones; two parts stepping in two threads, their
// exchange a fake all-gather between the threads, advance the replicated
// nodes bit-identically on both parts and to the serial run's values to
// round-off (summation order); shareStates brings every element's history
// to both parts; the partition covers every element once and names each
// element's owner, by default in blocks, after shareOut by count within
// the marked elements and within the others (the two-part step then as
// serial to round-off as well). PackedValues: sums (in part order), minima, maxima and
// owned values combined in one exchange, the same bits on every part; a
// probe recovered from its patch elements' samples packed by their owners
// has the bits of the probe evaluated from the shared histories.
#include "ExplicitSolver.H"
#include "ModelSnapshot.H"
#include "Partition.H"
#include "PointProbe.H"
#include "SolidError.H"
#include "SolidTestUtils.H"

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <cstdio>
#include <mutex>
#include <random>
#include <thread>

using namespace solid;

namespace
{

//- The exchange of nParts threads: each deposits its values, waits for
//  the others, copies all in part order, waits again (so that no part
//  overwrites its values before every part has copied them)
class ThreadGather
{
    std::mutex mutex_;
    std::condition_variable cv_;
    const int nParts_;
    int arrived_ = 0;
    long generation_ = 0;
    std::vector<std::vector<double>> data_;

    void barrier(std::unique_lock<std::mutex>& lock)
    {
        const long g = generation_;
        if (++arrived_ == nParts_)
        {
            arrived_ = 0;
            ++generation_;
            cv_.notify_all();
        }
        else
        {
            cv_.wait(lock, [&] { return generation_ != g; });
        }
    }

public:

    explicit ThreadGather(int nParts) : nParts_(nParts), data_(nParts) {}

    Partition::AllGather of(int part)
    {
        return [this, part](const double* mine, std::size_t n, double* all)
        {
            std::unique_lock<std::mutex> lock(mutex_);
            data_[part].assign(mine, mine + n);
            barrier(lock);
            for (int r = 0; r < nParts_; ++r)
            {
                std::copy(data_[r].begin(), data_[r].end(), all + r*n);
            }
            barrier(lock);
        };
    }
};

//- A distorted bar of 7 x 2 x 2 hexahedra of the cell's cytoplasm (Mie-
//  Grueneisen, a Maxwell branch: element and point histories), fixed at
//  xmin, with random initial velocities (the same on every call);
//  reversed: the elements listed in the reverse order (the same model,
//  its nodal sums in another order)
std::unique_ptr<Model> bar(bool reversed = false)
{
    const double h = 1e-6;
    Mesh m = Mesh::box(7, 2, 2, Vec3(0, 0, 0), Vec3(7*h, 2*h, 2*h));
    solidTest::distortInterior(m, h, 0.2, 5);
    if (reversed)
    {
        const int nen = m.nen(), ne = m.nElements();
        std::vector<int> conn(m.conn.size());
        for (int e = 0; e < ne; ++e)
        {
            std::copy
            (
                m.element(ne - 1 - e), m.element(ne - 1 - e) + nen,
                conn.begin() + nen*e
            );
        }
        m.conn = conn;
        std::reverse(m.region.begin(), m.region.end());
    }
    std::unique_ptr<Model> model(new Model(m));
    model->setMaterial(m.regionNames[0], solidTest::cytoplasm());
    for (int i = 0; i < 3; ++i) model->fix("xmin", i);
    return model;
}

void start(Model& m)
{
    m.initialise();
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int d = 0; d < m.v.size(); ++d) m.v(d) = u(gen);
    for (const int d : m.prescribedDofs()) m.v(d) = 0;
}

//- The tutorial's viscosities: hourglass, filtered deviatoric
ExplicitSettings settings()
{
    ExplicitSettings set;
    set.hourglass = 0.1;
    set.shearViscosity = 0.2;
    set.shearViscosityFilter = true;
    return set;
}

double relDiff(const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
    return (a - b).lpNorm<Eigen::Infinity>()
       /std::max(b.lpNorm<Eigen::Infinity>(), 1e-300);
}

//- The committed histories of a model built by bar(true), in the
//  element order of bar()
std::vector<double> unreversed(const StateArray& s)
{
    std::vector<double> x;
    const int ne = int(s.nItems());
    for (int e = 0; e < ne; ++e)
    {
        x.insert(x.end(), s.old(ne - 1 - e), s.old(ne - 1 - e) + s.size(e));
    }
    return x;
}

double relDiff(const std::vector<double>& a, const std::vector<double>& b)
{
    return relDiff
    (
        Eigen::Map<const Eigen::VectorXd>(a.data(), a.size()),
        Eigen::Map<const Eigen::VectorXd>(b.data(), b.size())
    );
}

} // namespace


TEST(partition, ownsEveryElementOnce)
{
    for (const int n : {0, 1, 5, 28, 2085})
    {
        for (const int parts : {1, 2, 3, 7})
        {
            std::vector<int> owners(n, 0);
            int previousEnd = 0;
            for (int p = 0; p < parts; ++p)
            {
                const Partition P(p, parts, [](const double*, std::size_t,
                                               double*) {});
                EXPECT_EQ(P.begin(n), previousEnd);
                for (int e = P.begin(n); e < P.end(n); ++e) ++owners[e];
                // Balanced: block sizes differ by at most one
                EXPECT_LE(P.end(n) - P.begin(n), n/parts + 1);
                EXPECT_GE(P.end(n) - P.begin(n), n/parts);
                previousEnd = P.end(n);
            }
            EXPECT_EQ(previousEnd, n);
            for (const int c : owners) EXPECT_EQ(c, 1);
        }
    }
    EXPECT_THROW(Partition(2, 2, {}), SolidError);
    EXPECT_THROW(Partition(0, 0, {}), SolidError);
    EXPECT_THROW(Partition(0, 2, {}), SolidError);      // no exchange
    EXPECT_NO_THROW(Partition(0, 1, {}));
}


TEST(partition, combineSumsInPartOrderMinMax)
{
    // Three parts in three threads: sums in part order, minima, maxima;
    // the same bits on every part
    ThreadGather g(3);
    std::vector<std::vector<double>> x(3);
    std::vector<std::thread> threads;
    for (int p = 0; p < 3; ++p)
    {
        x[p] = {1e16*(p == 0) + 1.0, double(p), double(p), -double(p)};
        threads.emplace_back([&, p]
        {
            Partition(p, 3, g.of(p)).combine(x[p].data(), 2, 1, 1);
        });
    }
    for (auto& t : threads) t.join();
    for (int p = 0; p < 3; ++p)
    {
        // (1e16 + 1) + 1 + 1 in part order
        EXPECT_EQ(x[p][0], (1e16 + 1.0) + 1.0 + 1.0);
        EXPECT_EQ(x[p][1], 3.0);
        EXPECT_EQ(x[p][2], 0.0);
        EXPECT_EQ(x[p][3], 0.0);
        EXPECT_EQ(x[p], x[0]);
    }
}


TEST(partition, partialForcesSumToSerial)
{
    // Each part's assemble over its own elements (not combined): the sum
    // of the parts' internal forces and energies is the serial one
    auto serial = bar();
    start(*serial);
    serial->u = 1e-3*serial->v*1e-6;
    Assembly as;
    serial->assemble(serial->u, serial->pressure, 0, 1e-12, false, as);
    Eigen::VectorXd sum(Eigen::VectorXd::Zero(as.fint.size()));
    double energy = 0;
    double stableDt = 1e300;
    for (int p = 0; p < 2; ++p)
    {
        auto m = bar();
        m->setPartition(Partition(p, 2, [](const double*, std::size_t,
                                           double*) { FAIL(); }));
        start(*m);
        m->u = serial->u;
        Assembly a;
        m->assemble(m->u, m->pressure, 0, 1e-12, false, a, false);
        sum += a.fint;
        energy += a.energy;
        stableDt = std::min(stableDt, a.stableDt);
        // Each part's share is not the whole
        EXPECT_GT(relDiff(a.fint, as.fint), 1e-3);
        // The tangent is refused on a shared model
        EXPECT_THROW
        (
            m->assemble(m->u, m->pressure, 0, 1e-12, true, a, false),
            SolidError
        );
    }
    std::printf("parts' internal force sum against serial: %.3e relative\n",
        relDiff(sum, as.fint));
    EXPECT_LT(relDiff(sum, as.fint), 1e-13);
    EXPECT_NEAR(energy, as.energy, 1e-13*std::abs(as.energy));
    EXPECT_EQ(stableDt, as.stableDt);
}


namespace
{

//- The marks of twoPartsStepAsSerial's shared-out run: the first third
//  of the bar's elements (blocks would give them all to part 0)
std::vector<bool> firstThird(int ne)
{
    std::vector<bool> marked(ne, false);
    for (int e = 0; e < ne/3; ++e) marked[e] = true;
    return marked;
}

//- The bar stepped by the serial solver, the serial solver with the
//  elements reversed (the scale of round-off), and two parts in two
//  threads, their elements in the default blocks or (sharedOut) shared
//  out by firstThird
void twoPartsStepAsSerial(const bool sharedOut)
{
    // The serial run and, for the scale of round-off, the serial run with
    // its elements in the reverse order (its nodal sums in another order,
    // as the parts' are): the 2 parts must differ from the serial run by
    // no more than a few times what that reordering alone gives
    const int steps = 200;
    auto serial = bar();
    start(*serial);
    ExplicitSolver s(*serial, settings());
    for (int i = 0; i < steps; ++i) s.step();
    auto reordered = bar(true);
    start(*reordered);
    ExplicitSolver r(*reordered, settings());
    for (int i = 0; i < steps; ++i) r.step();
    const ExplicitState rs = r.state();

    ThreadGather g(2);
    std::vector<std::unique_ptr<Model>> m(2);
    std::vector<ExplicitState> st(2);
    for (int p = 0; p < 2; ++p)
    {
        m[p] = bar();
        Partition part(p, 2, g.of(p));
        if (sharedOut)
        {
            part.shareOut(firstThird(m[p]->mesh().nElements()));
            // Not the default blocks: the comparison is not the blocks'
            EXPECT_NE
            (
                part.elements(m[p]->mesh().nElements()),
                Partition(p, 2, g.of(p)).elements(m[p]->mesh().nElements())
            );
        }
        m[p]->setPartition(std::move(part));
        start(*m[p]);
    }
    std::vector<std::thread> threads;
    for (int p = 0; p < 2; ++p)
    {
        threads.emplace_back([&, p]
        {
            ExplicitSolver solver(*m[p], settings());
            for (int i = 0; i < steps; ++i) solver.step();
            m[p]->shareStates();
            st[p] = solver.state();
        });
    }
    for (auto& t : threads) t.join();

    const ExplicitState ss = s.state();
    std::printf("2 parts (%s) against serial after %d steps: u %.3e, v %.3e, "
        "a %.3e, fint %.3e, fhg %.3e, point states %.3e, internal "
        "energy %.3e, hourglass dissipation %.3e relative\n",
        sharedOut ? "shared out" : "blocks", steps,
        relDiff(m[0]->u, serial->u), relDiff(m[0]->v, serial->v),
        relDiff(st[0].a, ss.a), relDiff(st[0].fint, ss.fint),
        relDiff(st[0].fhg, ss.fhg),
        relDiff(m[0]->pointState().oldData(),
                serial->pointState().oldData()),
        std::abs(st[0].energy.internal/ss.energy.internal - 1),
        std::abs(st[0].energy.hourglass/ss.energy.hourglass - 1));
    // The replicated nodes: the same bits on both parts
    EXPECT_EQ(m[0]->u, m[1]->u);
    EXPECT_EQ(m[0]->v, m[1]->v);
    EXPECT_EQ(st[0].a, st[1].a);
    EXPECT_EQ(st[0].dt, st[1].dt);
    EXPECT_EQ(m[0]->pointState().oldData(), m[1]->pointState().oldData());
    EXPECT_EQ(m[0]->elementState().oldData(),
              m[1]->elementState().oldData());
    // Against serial: round-off, as the reordered serial run (which
    // itself differs from the serial run: the comparison is not empty)
    const double
        du = relDiff(reordered->u, serial->u),
        dv = relDiff(reordered->v, serial->v),
        dfint = relDiff(rs.fint, ss.fint),
        dfhg = relDiff(rs.fhg, ss.fhg),
        dps = relDiff(unreversed(reordered->pointState()),
                      serial->pointState().oldData()),
        des = relDiff(unreversed(reordered->elementState()),
                      serial->elementState().oldData());
    std::printf("reordered serial against serial: u %.3e, v %.3e, fint "
        "%.3e, fhg %.3e, point states %.3e, element states %.3e "
        "relative\n", du, dv, dfint, dfhg, dps, des);
    EXPECT_GT(ss.energy.hourglass, 0);
    EXPECT_GT(dv, 0);
    EXPECT_GT(dfint, 0);
    const double f = 10;
    EXPECT_LT(relDiff(m[0]->u, serial->u), f*du);
    EXPECT_LT(relDiff(m[0]->v, serial->v), f*dv);
    EXPECT_LT(relDiff(st[0].fint, ss.fint), f*dfint);
    EXPECT_LT(relDiff(st[0].fhg, ss.fhg), f*dfhg);
    EXPECT_LT(relDiff(m[0]->pointState().oldData(),
                      serial->pointState().oldData()), f*dps);
    EXPECT_LT(relDiff(m[0]->elementState().oldData(),
                      serial->elementState().oldData()), f*des);
    // and small in absolute terms
    EXPECT_LT(relDiff(m[0]->u, serial->u), 1e-12);
    EXPECT_LT(relDiff(m[0]->v, serial->v), 1e-10);
    EXPECT_NEAR(st[0].dt, ss.dt, 1e-12*ss.dt);
    EXPECT_NEAR(st[0].energy.internal, ss.energy.internal,
                1e-10*std::abs(ss.energy.internal));
    EXPECT_NEAR(st[0].energy.hourglass, ss.energy.hourglass,
                1e-10*std::abs(ss.energy.hourglass));
    EXPECT_NEAR(st[0].energy.balance(), ss.energy.balance(),
                1e-10*std::abs(ss.energy.kinetic));
}

} // namespace


TEST(partition, twoPartsStepAsSerial)
{
    twoPartsStepAsSerial(false);
}


TEST(partition, twoPartsSharedOutStepAsSerial)
{
    // The elements shared out by count in two classes: the same
    // replicated nodes on both parts, the serial values to round-off
    twoPartsStepAsSerial(true);
}


TEST(partition, shareStatesOfSomeElements)
{
    // Histories of listed elements only: from their owners to both parts;
    // the other elements keep each part's own values
    ThreadGather g(2);
    std::vector<std::unique_ptr<Model>> m(2);
    for (int p = 0; p < 2; ++p)
    {
        m[p] = bar();
        m[p]->setPartition(Partition(p, 2, g.of(p)));
        start(*m[p]);
        // Marks: part p writes p + 1 into every element's blocks
        for (StateArray* s : {&m[p]->pointState(), &m[p]->elementState()})
        {
            std::fill(s->oldData().begin(), s->oldData().end(), p + 1.0);
        }
    }
    const int ne = m[0]->mesh().nElements();
    const std::vector<int> listed = {0, ne/2 - 1, ne/2, ne - 1};
    std::vector<std::thread> threads;
    for (int p = 0; p < 2; ++p)
    {
        threads.emplace_back([&, p] { m[p]->shareStates(listed); });
    }
    for (auto& t : threads) t.join();
    for (int p = 0; p < 2; ++p)
    {
        const StateArray& s = m[p]->pointState();
        for (int e = 0; e < ne; ++e)
        {
            const bool isListed =
                std::find(listed.begin(), listed.end(), e) != listed.end();
            const double owner = e < ne/2 ? 1.0 : 2.0;
            ASSERT_GT(s.size(e), 0);
            EXPECT_EQ(s.old(e)[0], isListed ? owner : p + 1.0) << e;
            if (isListed)
            {
                EXPECT_EQ(s.current(e)[0], owner) << e;
            }
        }
    }
}


TEST(partition, ownerOfEveryElement)
{
    for (const int n : {1, 5, 28, 2085})
    {
        for (const int parts : {1, 2, 3, 7})
        {
            for (int p = 0; p < parts; ++p)
            {
                const Partition P(p, parts, [](const double*, std::size_t,
                                               double*) {});
                for (int e = 0; e < n; ++e)
                {
                    const bool mine = e >= P.begin(n) && e < P.end(n);
                    EXPECT_EQ(P.owner(e, n) == p, mine) << e << " of " << n;
                }
            }
        }
    }
    const Partition P(1, 2, [](const double*, std::size_t, double*) {});
    EXPECT_THROW(P.owner(-1, 5), SolidError);
    EXPECT_THROW(P.owner(5, 5), SolidError);
}


TEST(partition, shareOutByCountInEachClass)
{
    // Every element owned by one part, owner() and elements() agreeing,
    // each class shared by count (within 1), in increasing index order;
    // without marks the default blocks
    std::mt19937 gen(3);
    std::bernoulli_distribution coin(0.3);
    for (const int n : {0, 1, 5, 28, 2085})
    {
        std::vector<bool> marked(n), none(n, false);
        for (int e = 0; e < n; ++e) marked[e] = coin(gen);
        const int nMarked = int(std::count(marked.begin(), marked.end(), true));
        for (const int parts : {1, 2, 3, 7})
        {
            std::vector<int> owners(n, 0);
            for (int p = 0; p < parts; ++p)
            {
                Partition P(p, parts, [](const double*, std::size_t,
                                         double*) {});
                const std::vector<int> blocks = P.elements(n);
                EXPECT_FALSE(P.sharedOut());
                Partition Q(P);
                Q.shareOut(none);
                EXPECT_TRUE(Q.sharedOut());
                EXPECT_EQ(Q.elements(n), blocks) << n << ' ' << parts;
                P.shareOut(marked);
                const std::vector<int> mine = P.elements(n);
                EXPECT_TRUE(std::is_sorted(mine.begin(), mine.end()));
                int m = 0;
                for (const int e : mine)
                {
                    ++owners[e];
                    if (marked[e]) ++m;
                    EXPECT_EQ(P.owner(e, n), p);
                }
                const int u = int(mine.size()) - m;
                EXPECT_GE(m, nMarked/parts);
                EXPECT_LE(m, nMarked/parts + 1);
                EXPECT_GE(u, (n - nMarked)/parts);
                EXPECT_LE(u, (n - nMarked)/parts + 1);
                for (int e = 0; e < n; ++e)
                {
                    const bool listed =
                        std::binary_search(mine.begin(), mine.end(), e);
                    EXPECT_EQ(P.owner(e, n) == p, listed) << e;
                }
            }
            for (int e = 0; e < n; ++e) EXPECT_EQ(owners[e], 1) << e;
        }
    }
    // Marks of 5 elements: asked for 6 (or element 5) is an error
    Partition P(0, 2, [](const double*, std::size_t, double*) {});
    P.shareOut(std::vector<bool>(5, true));
    EXPECT_THROW(P.owner(0, 6), SolidError);
    EXPECT_THROW(P.owner(5, 5), SolidError);
    // Set before the model's initialisation only
    auto m = bar();
    start(*m);
    EXPECT_THROW(m->setPartition(P), SolidError);
}


TEST(partition, packedValuesCombinedInOneExchange)
{
    // Three parts in three threads, the exchange counted: sums in part
    // order, minima, maxima and values owned by one part, interleaved
    ThreadGather g(3);
    int exchanges[3] = {0, 0, 0};
    std::vector<PackedValues> v(3);
    std::vector<std::size_t> at;
    std::mutex atMutex;
    std::vector<std::thread> threads;
    for (int p = 0; p < 3; ++p)
    {
        threads.emplace_back([&, p]
        {
            const Partition::AllGather gather = g.of(p);
            const Partition P(p, 3, [&, p, gather]
                (const double* mine, std::size_t n, double* all)
                {
                    ++exchanges[p];
                    gather(mine, n, all);
                });
            const double big[2] = {1e16*(p == 0) + 1.0, double(p)};
            const double m[2] = {double(p), -double(p)};
            const double own[3] = {10.0 + p, -0.0, 1e-300*p};
            const double other[2] = {-1.0*p, 2.0*p};
            PackedValues& x = v[p];
            std::vector<std::size_t> o;
            o.push_back(x.sum(big, 2));
            o.push_back(x.min(m, 1));
            o.push_back(x.max(m + 1, 1));
            // Owned by part 2, zeros on the others
            o.push_back(x.owned(2, p == 2 ? own : nullptr, 3));
            o.push_back(x.owned(0, own, 3));
            o.push_back(x.max(other, 2));
            o.push_back(x.sum(nullptr, 1));
            P.combine(x);
            if (p == 0)
            {
                std::lock_guard<std::mutex> lock(atMutex);
                at = o;
            }
        });
    }
    for (auto& t : threads) t.join();
    ASSERT_EQ(at.size(), 7u);
    EXPECT_EQ(at[0], 0u);
    EXPECT_EQ(at[3], 4u);
    EXPECT_EQ(at[6], 12u);
    for (int p = 0; p < 3; ++p)
    {
        EXPECT_EQ(exchanges[p], 1);
        const PackedValues& x = v[p];
        ASSERT_EQ(x.size(), 13u);
        // (1e16 + 1) + 1 + 1 in part order
        EXPECT_EQ(x[at[0]], (1e16 + 1.0) + 1.0 + 1.0);
        EXPECT_EQ(x[at[0] + 1], 3.0);
        EXPECT_EQ(x[at[1]], 0.0);
        EXPECT_EQ(x[at[2]], 0.0);
        // Part 2's values exactly, the sign of its zero too
        EXPECT_EQ(x[at[3]], 12.0);
        EXPECT_EQ(x[at[3] + 1], 0.0);
        EXPECT_TRUE(std::signbit(x[at[3] + 1]));
        EXPECT_EQ(x[at[3] + 2], 2e-300);
        EXPECT_EQ(x[at[4]], 10.0);
        EXPECT_EQ(x[at[4] + 2], 0.0);
        EXPECT_EQ(x[at[5]], 0.0);
        EXPECT_EQ(x[at[5] + 1], 4.0);
        EXPECT_EQ(x[at[6]], 0.0);
        for (std::size_t i = 0; i < x.size(); ++i)
        {
            EXPECT_EQ
            (
                std::memcmp(x.data() + i, v[0].data() + i, sizeof(double)),
                0
            ) << i;
        }
    }

    // One part: no exchange, the values as packed; cleared: empty
    PackedValues one;
    const double y[2] = {1.5, -0.0};
    one.owned(0, y, 1);
    one.sum(y + 1, 1);
    Partition().combine(one);
    EXPECT_EQ(one[0], 1.5);
    EXPECT_TRUE(std::signbit(one[1]));
    one.clear();
    EXPECT_EQ(one.size(), 0u);
    // An owner that is no part
    EXPECT_THROW(one.owned(-1, y, 1), SolidError);
    ThreadGather g2(2);
    std::vector<std::thread> t2;
    int thrown = 0;
    std::mutex thrownMutex;
    for (int p = 0; p < 2; ++p)
    {
        t2.emplace_back([&, p]
        {
            PackedValues z;
            z.owned(2, y, 1);
            try
            {
                Partition(p, 2, g2.of(p)).combine(z);
            }
            catch (const SolidError&)
            {
                std::lock_guard<std::mutex> lock(thrownMutex);
                ++thrown;
            }
        });
    }
    for (auto& t : t2) t.join();
    EXPECT_EQ(thrown, 2);
}


TEST(partition, probeFromOwnersSamplesAsFromSharedStates)
{
    // Two parts step the bar; a probe whose patch spans both parts'
    // elements is recovered (a) from the patch elements' samples each
    // part evaluates for the elements it owns, packed as owned values and
    // combined, and (b) as before: the histories shared (shareStates),
    // then evaluated on one part. The same bits on both parts
    const int steps = 50;
    ThreadGather g(2);
    std::vector<std::unique_ptr<Model>> m(2);
    for (int p = 0; p < 2; ++p)
    {
        m[p] = bar();
        m[p]->setPartition(Partition(p, 2, g.of(p)));
        start(*m[p]);
    }
    const double h = 1e-6;
    const PointProbe probe(m[0]->mesh(), Vec3(3.4*h, 0.9*h, 1.2*h), -1);
    const std::vector<int>& patch = probe.patch();
    const int ne = m[0]->mesh().nElements();
    int owners[2] = {0, 0};
    for (const int e : patch) ++owners[m[0]->partition().owner(e, ne)];
    ASSERT_GT(owners[0], 0);
    ASSERT_GT(owners[1], 0);

    std::vector<ProbeValues> fromSamples(2), fromStates(2);
    std::vector<std::thread> threads;
    for (int p = 0; p < 2; ++p)
    {
        threads.emplace_back([&, p]
        {
            Model& model = *m[p];
            ExplicitSolver solver(model, settings());
            for (int i = 0; i < steps; ++i) solver.step();
            const Partition& part = model.partition();
            PackedValues v;
            std::vector<std::size_t> at;
            for (const int e : patch)
            {
                const bool mine = part.owner(e, ne) == part.part();
                double x[21] = {};
                if (mine)
                {
                    const ProbeValues s =
                        PointProbe::sample(model.evaluateElement(e, 0));
                    x[0] = s.p;
                    std::copy(s.sigma.data(), s.sigma.data() + 9, x + 1);
                    std::copy(s.F.data(), s.F.data() + 9, x + 10);
                    x[19] = s.theta;
                    x[20] = s.temperatureRise;
                }
                at.push_back(v.owned(part.owner(e, ne), x, 21));
            }
            part.combine(v);
            std::vector<ProbeValues> samples(patch.size());
            for (std::size_t i = 0; i < patch.size(); ++i)
            {
                const double* x = v.data() + at[i];
                samples[i].p = x[0];
                std::copy(x + 1, x + 10, samples[i].sigma.data());
                std::copy(x + 10, x + 19, samples[i].F.data());
                samples[i].theta = x[19];
                samples[i].temperatureRise = x[20];
            }
            fromSamples[p] = probe.recover(samples);
            model.shareStates(patch);
            fromStates[p] = probe.evaluate(model);
        });
    }
    for (auto& t : threads) t.join();
    for (int p = 0; p < 2; ++p)
    {
        const ProbeValues& a = fromSamples[p];
        const ProbeValues& b = fromStates[p];
        EXPECT_EQ(a.p, b.p);
        EXPECT_EQ(a.sigma, b.sigma);
        EXPECT_EQ(a.F, b.F);
        EXPECT_EQ(a.theta, b.theta);
        EXPECT_EQ(a.temperatureRise, b.temperatureRise);
        EXPECT_EQ(a.p, fromSamples[0].p);
        EXPECT_EQ(a.sigma, fromSamples[0].sigma);
    }
    // Not a trivial state: stressed and deformed
    EXPECT_GT(fromSamples[0].sigma.norm(), 0);
    EXPECT_NE(fromSamples[0].theta, 1.0);
    // The samples must match the patch
    EXPECT_THROW(probe.recover(std::vector<ProbeValues>(1)), SolidError);
}


TEST(partition, stateRangesOfSomeItems)
{
    // Blocks of listed items as offset ranges, adjacent ones merged,
    // empty ones left out; commit and revert of those ranges only
    StateArray s;
    s.resize({2, 0, 3, 1, 2, 0, 4});
    using R = StateArray::Range;
    EXPECT_EQ(s.ranges({0, 1, 2, 3, 4, 5, 6}), std::vector<R>({R(0, 12)}));
    EXPECT_EQ(s.ranges({0, 2, 3, 6}), std::vector<R>({R(0, 6), R(8, 12)}));
    EXPECT_EQ(s.ranges({1, 5}), std::vector<R>());
    EXPECT_EQ(s.ranges({}), std::vector<R>());
    for (std::size_t i = 0; i < 12; ++i) s.currentData()[i] = i + 1.0;
    s.commit(s.ranges({2, 6}));
    for (std::size_t i = 0; i < 12; ++i)
    {
        const bool in = (i >= 2 && i < 5) || i >= 8;
        EXPECT_EQ(s.oldData()[i], in ? i + 1.0 : 0.0) << i;
    }
    s.revert(s.ranges({0, 6}));
    for (std::size_t i = 0; i < 12; ++i)
    {
        const bool reverted = i < 2 || i >= 8;
        EXPECT_EQ(s.currentData()[i], reverted ? s.oldData()[i] : i + 1.0)
            << i;
    }
}


namespace
{

//- n steps of two parts in two threads (their elements shared out by
//  firstThird), each part's body(part, model, solver) run after them
template<class Body>
void twoParts(std::vector<std::unique_ptr<Model>>& m, Body body)
{
    ThreadGather g(2);
    m.resize(2);
    for (int p = 0; p < 2; ++p)
    {
        m[p] = bar();
        Partition part(p, 2, g.of(p));
        part.shareOut(firstThird(m[p]->mesh().nElements()));
        m[p]->setPartition(std::move(part));
        start(*m[p]);
    }
    std::vector<std::thread> threads;
    for (int p = 0; p < 2; ++p)
    {
        threads.emplace_back([&, p]
        {
            ExplicitSolver solver(*m[p], settings());
            body(p, *m[p], solver);
        });
    }
    for (auto& t : threads) t.join();
}

} // namespace


TEST(partition, ownedSnapshotRestoresAStepBitwise)
{
    // What the FSI solver's ranks save and restore within a step: the
    // owned histories only (about half of them on each of 2 parts); steps
    // after a restore repeat the first attempt's bits, on both parts, and
    // the other elements' histories are left as they were; serial: the
    // owned snapshot is the whole one
    std::vector<std::unique_ptr<Model>> m;
    std::vector<Eigen::VectorXd> u1(2), v1(2);
    std::vector<std::vector<double>> ps1(2), es1(2), psBefore(2);
    std::vector<std::size_t> held(2);
    twoParts(m, [&](int p, Model& model, ExplicitSolver& solver)
    {
        for (int i = 0; i < 20; ++i) solver.step();
        const ModelSnapshot saved(model, ModelSnapshot::Histories::owned);
        const ExplicitState state = solver.state();
        held[p] = saved.part(ModelSnapshot::pointState).size();
        psBefore[p] = model.pointState().oldData();
        for (int i = 0; i < 5; ++i) solver.step();
        u1[p] = model.u;
        v1[p] = model.v;
        ps1[p] = model.pointState().oldData();
        es1[p] = model.elementState().oldData();
        saved.restore(model);
        solver.setState(state);
        // The owned histories restored, the others (stale copies) as they
        // were: the steps did not write them
        EXPECT_EQ(model.pointState().oldData(), psBefore[p]);
        for (int i = 0; i < 5; ++i) solver.step();
    });
    const std::size_t whole = m[0]->pointState().oldData().size();
    for (int p = 0; p < 2; ++p)
    {
        EXPECT_EQ(m[p]->u, u1[p]) << p;
        EXPECT_EQ(m[p]->v, v1[p]) << p;
        EXPECT_EQ(m[p]->pointState().oldData(), ps1[p]) << p;
        EXPECT_EQ(m[p]->elementState().oldData(), es1[p]) << p;
        // About half of the histories held
        EXPECT_GT(held[p], whole/4) << p;
        EXPECT_LT(held[p], 3*whole/4) << p;
    }
    EXPECT_EQ(held[0] + held[1], whole);
    EXPECT_EQ(m[0]->u, m[1]->u);

    // A snapshot of another partition's owned histories is refused
    auto serial = bar();
    start(*serial);
    const ModelSnapshot part0(*m[0], ModelSnapshot::Histories::owned);
    EXPECT_THROW(part0.restore(*serial), SolidError);
    // Serial: the owned snapshot is the whole one
    const ModelSnapshot all(*serial), owned
    (
        *serial, ModelSnapshot::Histories::owned
    );
    for (int i = 0; i < ModelSnapshot::nParts; ++i)
    {
        const auto part = ModelSnapshot::Part(i);
        EXPECT_EQ(owned.part(part), all.part(part)) << i;
    }
}


TEST(partition, partialFilteredShearForcesSumToSerial)
{
    // Each part's hourglass force (its dampers and the filtered shear
    // viscosity of its own elements, from the rates and slot averages of
    // their neighbourhood only) with an exchange that gives every part
    // its own values twice (so its combined force is twice its partial
    // one, exactly): the parts' partial forces sum to the serial force to
    // round-off, in the default blocks and shared out by firstThird
    auto serial = bar();
    start(*serial);
    const ExplicitSolver s(*serial, settings());
    const Eigen::VectorXd& fs = s.state().fhg;
    ASSERT_GT(fs.lpNorm<Eigen::Infinity>(), 0);
    for (const bool sharedOut : {false, true})
    {
        Eigen::VectorXd sum(Eigen::VectorXd::Zero(fs.size()));
        for (int p = 0; p < 2; ++p)
        {
            auto m = bar();
            Partition part
            (
                p, 2, [](const double* mine, std::size_t n, double* all)
                {
                    std::copy(mine, mine + n, all);
                    std::copy(mine, mine + n, all + n);
                }
            );
            if (sharedOut) part.shareOut(firstThird(m->mesh().nElements()));
            m->setPartition(std::move(part));
            start(*m);
            const ExplicitSolver solver(*m, settings());
            const Eigen::VectorXd partial = 0.5*solver.state().fhg;
            EXPECT_GT(relDiff(partial, fs), 1e-3);
            sum += partial;
        }
        std::printf("parts' hourglass and filtered shear force sum (%s) "
            "against serial: %.3e relative\n",
            sharedOut ? "shared out" : "blocks", relDiff(sum, fs));
        EXPECT_LT(relDiff(sum, fs), 1e-13);
    }
}
