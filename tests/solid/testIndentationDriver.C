// The indentation driver (solid::IndentationDriver) on a small r-z block:
// the force-controlled first row ends at its target force, the steps of a
// hold grow geometrically while the force relaxes, and a run continued
// from a checkpoint (its outputs longer than at the checkpoint, as after
// a kill) equals the uninterrupted run bit for bit.
#include "IndentationDriver.H"
#include "Checkpoint.H"
#include "Hdf5File.H"
#include "SolidError.H"
#include "SolidTestUtils.H"
#include "fileDigest.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

using namespace solid;
namespace fs = std::filesystem;

namespace
{

//- A scratch directory, removed at the end of the test
struct ScratchDir
{
    std::string path;
    ScratchDir()
    {
        std::string t =
            (fs::temp_directory_path()/"indentationDriverXXXXXX").string();
        path = mkdtemp(&t[0]);
    }
    ~ScratchDir() { fs::remove_all(path); }
};

//- The block (10 x 5 um, r-z, incompressible, one Maxwell branch with
//  tau = 0.5 s) under a 5 um sphere, with its driver
struct Indentation
{
    std::unique_ptr<Model> model;
    std::shared_ptr<RigidSphereContact> contact;
    std::shared_ptr<IndentationProtocol> protocol;
    std::unique_ptr<IndentationDriver> driver;

    Indentation
    (
        const std::vector<ProtocolRow>& rows,
        const IndentationSettings& settings,
        const std::string& outDir
    )
    {
        model.reset(new Model(Mesh::rectangle(6, 4, 0, 10e-6, 0, 5e-6)));
        model->setMaterial
        (
            "solid", solidTest::material(100, 0, {{200, 0.5}})
        );
        model->fix("bottom", 0);
        model->fix("bottom", 1);
        model->fix("left", 0);
        protocol = std::make_shared<IndentationProtocol>(rows);
        RigidSphereSettings s;
        s.radius = 5e-6;
        s.tolerance = 1e-9;
        s.centre0 = Vec3(0, 5e-6 + s.radius, 0);
        s.direction = Vec3(0, -1, 0);
        auto p = protocol;
        s.depth = [p](double t) { return p->depth(t); };
        contact = std::make_shared<RigidSphereContact>("top", s);
        model->add(contact);
        model->initialise();
        NewtonSettings newton;
        newton.maxCuts = 10;
        driver.reset
        (
            new IndentationDriver
            (
                *model, contact, protocol, newton, settings, outDir
            )
        );
    }
};

//- Rows of force.dat (time, depth, force, radius, penetration) by stage
struct ForceRow
{
    double t, depth, force;
    std::string stage;
};

std::vector<ForceRow> forceRows(const std::string& dir)
{
    std::ifstream is(dir + "/force.dat");
    std::vector<ForceRow> rows;
    std::string line;
    while (std::getline(is, line))
    {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ls(line);
        ForceRow r;
        double radius, penetration;
        ls >> r.t >> r.depth >> r.force >> radius >> penetration >> r.stage;
        rows.push_back(r);
    }
    return rows;
}

std::string contents(const std::string& file)
{
    std::ifstream is(file, std::ios::binary);
    std::ostringstream os;
    os << is.rdbuf();
    return os.str();
}

IndentationSettings baseSettings()
{
    IndentationSettings s;
    s.maxDepthIncrement = 0.1e-6;   // [m]
    s.holdDeltaT0 = 0.01;           // [s]
    s.maxDeltaT = 0.5;              // [s]
    s.holdGrowth = 1.5;
    s.checkpointInterval = 0;
    s.precision = 17;               // force.dat read back exactly
    return s;
}

const std::vector<ProtocolRow> table =
{
    {"A", "load", 1e-6, 1e-6},
    {"B", "hold", 0, 2},
    {"C", "load", 1e-6, 0.3e-6},
    {"C", "unload", 1e-6, 0.3e-6},
    {"E", "hold", 0, 1}
};

} // namespace


TEST(SolidIndentationDriver, ForceControlledFirstRowReachesItsTarget)
{
    ScratchDir byDepth, byForce;
    IndentationSettings s = baseSettings();
    Indentation a(table, s, byDepth.path);
    a.driver->start(false);
    a.driver->run();
    const auto ra = forceRows(byDepth.path);
    double fA = 0;
    for (const auto& r : ra) if (r.stage == "A") fA = r.force;
    ASSERT_GT(fA, 0);

    // Half the force reached at 1 um: the first row ends there, shorter
    s.forceTarget = 0.5*fA;
    s.forceTargetTolerance = 1e-3;
    Indentation b(table, s, byForce.path);
    b.driver->start(false);
    b.driver->run();
    const auto rb = forceRows(byForce.path);
    const ForceRow* lastA = nullptr;
    for (const auto& r : rb) if (r.stage == "A") lastA = &r;
    ASSERT_TRUE(lastA);
    std::printf
    (
        "force target %.4e N: reached %.4e N at depth %.4e m, t = %.4f s\n",
        s.forceTarget, lastA->force, lastA->depth, lastA->t
    );
    EXPECT_LE(std::abs(lastA->force/s.forceTarget - 1), 1e-3);
    EXPECT_LT(lastA->depth, 1e-6);
    // The table now starts with that depth: later rows shift in time
    EXPECT_DOUBLE_EQ(b.protocol->rows()[0].amount, lastA->depth);
    EXPECT_DOUBLE_EQ(b.protocol->rowEnd(0), lastA->t);
    EXPECT_DOUBLE_EQ(rb.back().t, b.protocol->endTime());
}


// A force target above the force at the first row's full amount: refused
// at the row's end, naming forceTarget (adv30 n21: the run went on with
// the table's depth, no word that the target was not reached)
TEST(SolidIndentationDriver, ForceTargetNotReachedIsAnError)
{
    ScratchDir dir;
    IndentationSettings s = baseSettings();
    s.forceTarget = 1e-3;           // [N], far above the force at 1 um
    Indentation a(table, s, dir.path);
    a.driver->start(false);
    try
    {
        a.driver->run();
        FAIL() << "a force target not reached was accepted";
    }
    catch (const SolidError& e)
    {
        const std::string m = e.what();
        EXPECT_NE(m.find("'forceTarget' = 0.001 N was not reached"),
                  std::string::npos) << m;
        EXPECT_NE(m.find("full amount 1e-06 m"), std::string::npos) << m;
    }
}


TEST(SolidIndentationDriver, HoldStepsGrowAndTheForceRelaxes)
{
    ScratchDir dir;
    const IndentationSettings s = baseSettings();
    Indentation a(table, s, dir.path);
    a.driver->start(false);
    a.driver->run();
    std::vector<ForceRow> hold;
    double tA = 0;
    for (const auto& r : forceRows(dir.path))
    {
        if (r.stage == "A") tA = r.t;
        if (r.stage == "B") hold.push_back(r);
    }
    ASSERT_GE(hold.size(), 5u);
    // dt = 0.01 s x 1.5^k up to maxDeltaT, the last one cut to the end
    double t = tA, dt = s.holdDeltaT0;
    for (std::size_t k = 0; k + 1 < hold.size(); ++k)
    {
        EXPECT_NEAR(hold[k].t - t, std::min(dt, s.maxDeltaT), 1e-12);
        t = hold[k].t;
        dt *= s.holdGrowth;
    }
    EXPECT_DOUBLE_EQ(hold.back().t, a.protocol->rowEnd(1));
    for (std::size_t k = 1; k < hold.size(); ++k)
    {
        EXPECT_LT(hold[k].force, hold[k - 1].force);
        EXPECT_DOUBLE_EQ(hold[k].depth, hold[0].depth);
    }
    // The stage end (B) and the cycle's peak in peaks.dat
    const std::string peaks = contents(dir.path + "/peaks.dat");
    EXPECT_NE(peaks.find("\nendB "), std::string::npos) << peaks;
    EXPECT_NE(peaks.find("\nC,i "), std::string::npos) << peaks;
    EXPECT_NE(peaks.find("\nendE "), std::string::npos) << peaks;
}


// Rows of more steps than ln(DBL_MAX/holdDeltaT0)/ln(holdGrowth) (311 at
// 1e-3 s and 10): the hold step, grown at every step of a row and stored
// uncapped, overflowed to inf, a sigFpe under OpenFOAM's trapping (adv35
// s15, s16, s20: cellIndentationFoam died at t = 0.177 s of a load row of
// 1e-4 s steps). Run in a child process with the traps OpenFOAM sets: a
// trap fails this test only. Both a load row and a hold row are longer
// than 311 steps; every step is maxDeltaT. (The default "fast" death
// test style: the child writes into this test's scratch directory.)
TEST(SolidIndentationDriver, RowsOfManyStepsDoNotOverflowTheStep)
{
    ScratchDir dir;
    IndentationSettings s = baseSettings();
    s.holdGrowth = 10;              // the top of its range [1, 10]
    s.holdDeltaT0 = 1e-3;           // [s]
    s.maxDeltaT = 1e-3;             // [s]
    const std::vector<ProtocolRow> longRows =
    {
        {"A", "load", 1e-6, 0.35e-6},   // 0.35 s: 350 steps
        {"B", "hold", 0, 0.35}          // 350 steps
    };
    EXPECT_EXIT
    (
        {
            Indentation a(longRows, s, dir.path);
            a.driver->start(false);
            feclearexcept(FE_ALL_EXCEPT);
            feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
            a.driver->run();
            fedisableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
            std::exit(0);
        },
        ::testing::ExitedWithCode(0),
        ""
    );
    const auto rows = forceRows(dir.path);
    std::size_t nA = 0, nB = 0;
    double t = 0;
    for (std::size_t k = 0; k < rows.size(); ++k)
    {
        (rows[k].stage == "A" ? nA : nB) += 1;
        if (k + 1 < rows.size())
        {
            EXPECT_NEAR(rows[k].t - t, s.maxDeltaT, 1e-9) << "row " << k;
        }
        t = rows[k].t;
    }
    EXPECT_GE(nA, 350u);
    EXPECT_GE(nB, 350u);
    ASSERT_FALSE(rows.empty());
    EXPECT_NEAR(rows.back().t, 0.7, 1e-9);
}

namespace
{

//- Run the table with a checkpoint every k steps (of n; the last one after
//  step k: k > n/2, when force.dat has lines lines), copy the outputs (a
//  run killed after that checkpoint: they carry more steps) and continue
//  from them; the continued run must equal the uninterrupted one bit for
//  bit
void resumeAfter
(
    long k,
    long lines,
    const IndentationSettings& settings,
    long n
)
{
    ASSERT_GT(2*k, n);
    ScratchDir whole, resumed;
    IndentationSettings s = settings;
    s.checkpointInterval = k;
    Indentation a(table, s, whole.path);
    a.driver->start(false);
    a.driver->run();
    ASSERT_TRUE(Checkpoint::exists(a.driver->checkpointFile()));
    fs::copy(whole.path, resumed.path, fs::copy_options::recursive
           | fs::copy_options::overwrite_existing);

    Indentation b(table, s, resumed.path);
    b.driver->start(true);
    EXPECT_EQ(b.driver->counters().steps, k);
    EXPECT_EQ(forceRows(resumed.path).size(), std::size_t(lines));
    b.driver->run();

    EXPECT_EQ(contents(whole.path + "/force.dat"),
              contents(resumed.path + "/force.dat"));
    EXPECT_EQ(contents(whole.path + "/peaks.dat"),
              contents(resumed.path + "/peaks.dat"));
    // the digests line by line (issue 19 class 5, adv52 p31): the same
    // for the continued run, and the last one that of the whole file
    for (const char* f : {"/force.dat", "/peaks.dat"})
    {
        const std::string side(contents(resumed.path + f + ".fnv1a64"));
        EXPECT_EQ(contents(whole.path + f + ".fnv1a64"), side) << f;
        const std::string data(contents(resumed.path + f));
        const std::string last
        (
            std::to_string(data.size()) + " " + fileDigest::hex
            (
                fileDigest::add(fileDigest::basis, data.data(), data.size())
            ) + "\n"
        );
        ASSERT_GE(side.size(), last.size()) << f;
        EXPECT_EQ(side.substr(side.size() - last.size()), last) << f;
        // one digest line per line of the file
        EXPECT_EQ
        (
            std::count(side.begin(), side.end(), '\n'),
            std::count(data.begin(), data.end(), '\n')
        ) << f;
    }
    EXPECT_EQ(a.driver->counters().steps, b.driver->counters().steps);
    EXPECT_EQ(a.driver->counters().iterations,
              b.driver->counters().iterations);
    EXPECT_TRUE(a.model->u == b.model->u);
    EXPECT_TRUE(a.model->pressure == b.model->pressure);
    EXPECT_EQ(a.model->time, b.model->time);
    const auto sa = ResultWriter::steps(whole.path + "/solid.h5");
    const auto sb = ResultWriter::steps(resumed.path + "/solid.h5");
    EXPECT_EQ(sa, sb);
    ASSERT_FALSE(sb.empty());
    Indentation fa(table, s, whole.path), fb(table, s, resumed.path);
    ResultWriter::restart(whole.path + "/solid.h5", sa.back().first,
                          *fa.model);
    ResultWriter::restart(resumed.path + "/solid.h5", sb.back().first,
                          *fb.model);
    EXPECT_TRUE(fa.model->u == fb.model->u);
    EXPECT_TRUE(fa.model->pressure == fb.model->pressure);

    // A checkpoint of another table is refused, the outputs untouched
    const std::string before = contents(resumed.path + "/force.dat");
    std::vector<ProtocolRow> shorter(table.begin(), table.begin() + 1);
    Indentation c(shorter, s, resumed.path);
    EXPECT_THROW(c.driver->start(true), SolidError);
    EXPECT_EQ(contents(resumed.path + "/force.dat"), before);
}

} // namespace


// Checkpoints inside a load row (the predictor u + dt v of the next step
// needs the rate) and inside a hold (the next step size): both restored
TEST(SolidIndentationDriver, ResumedRunEqualsUninterruptedBitForBit)
{
    ScratchDir first;
    IndentationSettings s = baseSettings();
    s.forceTarget = 1e-9;           // below the force at 1 um
    s.writeInterval = 0.5;          // fields [s]
    Indentation a(table, s, first.path);
    a.driver->start(false);
    a.driver->run();
    const auto rows = forceRows(first.path);
    const long n = a.driver->counters().steps;
    // The steps of the force-controlled row redone by the secant search
    // have no line in force.dat
    const long redone = n - long(rows.size());
    ASSERT_GT(n, 20);
    ASSERT_GE(redone, 1);

    // The first step k > n/2 that ends inside a load row, and inside a hold
    long kLoad = 0, kHold = 0;
    for (long k = n/2 + 1; k < n; ++k)
    {
        const double t = rows[k - redone - 1].t;
        const int r = a.protocol->rowAt(t);
        const bool inside = t < a.protocol->rowEnd(r)*(1 - 1e-9);
        const bool hold = a.protocol->rows()[r].motion == "hold";
        if (inside && hold && !kHold) kHold = k;
        if (inside && !hold && !kLoad) kLoad = k;
    }
    ASSERT_GT(kLoad, 0);
    ASSERT_GT(kHold, 0);
    std::printf("%ld steps; continued after step %ld (load) and %ld (hold)\n",
                n, kLoad, kHold);
    resumeAfter(kLoad, kLoad - redone, s, n);
    resumeAfter(kHold, kHold - redone, s, n);
}


// A resume continues only the outputs of the checkpoint's run, undamaged
// (issue 19, classes 1 and 5: force.dat or solid.h5 copied from another
// run, or solid.h5 damaged in a step before the checkpoint's, were
// continued silently); refused naming the file, nothing changed
TEST(SolidIndentationDriver, ResumeRefusesOutputsOfAnotherRunOrDamaged)
{
    ScratchDir own, other;
    IndentationSettings s = baseSettings();
    s.writeInterval = 0.5;          // fields [s]
    s.checkpointInterval = 10;
    s.runId = "runA";
    {
        Indentation a(table, s, own.path);
        a.driver->start(false);
        a.driver->run();
    }
    EXPECT_EQ(contents(own.path + "/force.dat").substr(0, 11),
              "# run runA\n");
    s.runId = "runB";
    {
        Indentation b(table, s, other.path);
        b.driver->start(false);
        b.driver->run();
    }
    const char* outputs[] = {"force.dat", "peaks.dat", "solid.h5",
                             "restart.h5"};
    // A resume with damage() done to a copy of the own run's outputs:
    // its error ("" if it continued), the outputs checked unchanged
    auto resume = [&](const std::function<void(const std::string&)>& damage)
    {
        ScratchDir c;
        fs::copy(own.path, c.path, fs::copy_options::recursive
               | fs::copy_options::overwrite_existing);
        damage(c.path);
        std::map<std::string, std::string> before;
        for (const char* f : outputs) before[f] = contents(c.path + "/" + f);
        Indentation r(table, s, c.path);
        std::string msg;
        try
        {
            r.driver->start(true);
        }
        catch (const SolidError& e)
        {
            msg = e.what();
            for (const char* f : outputs)
            {
                EXPECT_EQ(contents(c.path + "/" + f), before[f]) << f;
            }
        }
        return msg;
    };
    EXPECT_EQ(resume([](const std::string&) {}), "");
    for (const char* f : {"force.dat", "peaks.dat", "solid.h5"})
    {
        const std::string msg = resume([&](const std::string& dir)
        {
            fs::copy_file(other.path + "/" + f, dir + "/" + f,
                          fs::copy_options::overwrite_existing);
        });
        EXPECT_NE(msg.find(f), std::string::npos) << msg;
        EXPECT_NE(msg.find("belongs to another run"), std::string::npos)
            << msg;
        EXPECT_NE(msg.find("runA"), std::string::npos) << msg;
    }

    // One bit of the '# run' line flipped (adv42 g20: was "belongs to
    // another run"): the line named damaged (the file of another run of
    // the same inputs, above, differs in that line only: both named)
    for (const char* f : {"force.dat", "peaks.dat"})
    {
        const std::string msg = resume([&](const std::string& dir)
        {
            std::string bytes = contents(dir + "/" + f);
            ASSERT_EQ(bytes.compare(0, 10, "# run runA"), 0);
            bytes[8] ^= 0x01;
            std::ofstream(dir + "/" + f, std::ios::binary) << bytes;
        });
        EXPECT_NE(msg.find(std::string(f) + " is damaged in its first line"
                  ", or belongs to another run of the same inputs: its first"
                  " line is '# run ruoA' where this run wrote '# run runA'"),
                  std::string::npos) << msg;
    }

    // A missing output (adv33 c24: was "belongs to another run: its first
    // line is ''"): said to be missing
    for (const char* f : {"force.dat", "peaks.dat"})
    {
        const std::string msg = resume([&](const std::string& dir)
        {
            fs::remove(dir + "/" + f);
        });
        EXPECT_NE(msg.find(std::string(f) + " is missing"),
                  std::string::npos) << msg;
    }

    // A value of step 0 of solid.h5 zeroed (the checkpoint's steps later)
    const std::string msg = resume([](const std::string& dir)
    {
        const std::string h5 = dir + "/solid.h5";
        const std::vector<double> u =
            Hdf5File(h5, Hdf5File::Mode::readOnly).read("/steps/1/velocity");
        const double v = *std::max_element(u.begin(), u.end());
        std::string bytes = contents(h5);
        const auto at = bytes.find
        (
            std::string(reinterpret_cast<const char*>(&v), 8)
        );
        ASSERT_NE(at, std::string::npos);
        bytes.replace(at, 8, std::string(8, '\0'));
        std::ofstream(h5, std::ios::binary) << bytes;
    });
    EXPECT_NE(msg.find("solid.h5"), std::string::npos) << msg;
    EXPECT_NE(msg.find("/steps/1/velocity"), std::string::npos) << msg;
    EXPECT_NE(msg.find("checksum"), std::string::npos) << msg;

    // Zero bytes or a digit changed inside the rows of force.dat and
    // peaks.dat the checkpoint covers (adv35 k32, k33: continued without
    // a word, the damage kept); refused naming the file and the line
    for (const char* f : {"force.dat", "peaks.dat"})
    {
        const std::string zeroed = resume([&](const std::string& dir)
        {
            std::string bytes = contents(dir + "/" + f);
            const auto at = bytes.find('\n', bytes.find("\n") + 1) + 3;
            ASSERT_LT(at + 4, bytes.size());
            bytes.replace(at, 4, std::string(4, '\0'));
            std::ofstream(dir + "/" + f, std::ios::binary) << bytes;
        });
        EXPECT_NE(zeroed.find(std::string(f) + " changed after the run "
                  "wrote it"), std::string::npos) << zeroed;
        EXPECT_NE(zeroed.find("zero bytes from byte"), std::string::npos)
            << zeroed;
        EXPECT_NE(zeroed.find("(line 3)"), std::string::npos) << zeroed;
        const std::string edited = resume([&](const std::string& dir)
        {
            std::string bytes = contents(dir + "/" + f);
            const auto at = bytes.find_first_of
            (
                "123456789", bytes.find('\n', bytes.find('\n') + 1) + 1
            );
            ASSERT_NE(at, std::string::npos);
            bytes[at] = bytes[at] == '9' ? '8' : char(bytes[at] + 1);
            std::ofstream(dir + "/" + f, std::ios::binary) << bytes;
        });
        EXPECT_NE(edited.find(std::string(f) + " changed after the run "
                  "wrote it"), std::string::npos) << edited;
    }
}
