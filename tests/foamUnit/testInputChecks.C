/*---------------------------------------------------------------------------*\
Description
    Unit tests of the start-up checks of src/foamTools/inputChecks.H: an
    inverted mesh and non-positive time controls are errors naming the
    cell or the entry with its valid range; the one reader of bounded
    numbers (readInRange) takes every digit, honours open and closed
    bounds, and names the file, the entry, the value and the range of a
    missing entry, a word, list or sub-dictionary, a real for an integer
    or a value outside its range.

\*---------------------------------------------------------------------------*/

#include "inputChecks.H"
#include "foamTestCase.H"
#include "IStringStream.H"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

using namespace Foam;

namespace
{

autoPtr<fvMesh> cube(foamUnit::testCase& tc, const scalar mirror)
{
    const word p("patch");
    return tc.blockMesh
    (
        {2, 2, 2},
        [mirror](const vector& s)
        {
            return 1e-3*vector(mirror*s.x(), s.y(), s.z());
        },
        {"sides", "sides", "sides", "sides", "sides", "sides"},
        {p, p, p, p, p, p}
    );
}

} // End anonymous namespace


TEST(inputChecks, cellVolumes)
{
    {
        foamUnit::testCase tc("inputChecks");
        autoPtr<fvMesh> mesh = cube(tc, 1);
        EXPECT_NO_THROW(foamTools::checkCellVolumes(mesh()));
    }
    {
        // Mirrored points: every cell inverted, the first one named
        foamUnit::testCase tc("inputChecks");
        autoPtr<fvMesh> mesh = cube(tc, -1);
        try
        {
            foamTools::checkCellVolumes(mesh());
            ADD_FAILURE() << "an inverted mesh was accepted";
        }
        catch (const Foam::error& err)
        {
            for (const std::string m : {"cell 0 has volume -", "polyMesh"})
            {
                EXPECT_NE(err.message().find(m), std::string::npos)
                    << "no '" << m << "' in: " << err.message();
            }
        }
    }
}


TEST(inputChecks, timeControls)
{
    {
        foamUnit::testCase tc("inputChecks", 1e-6);
        EXPECT_NO_THROW
        (
            foamTools::checkTimeControls(tc.time(), true, 0.5, 1e-5)
        );
        try
        {
            foamTools::checkTimeControls(tc.time(), true, 0, 1e-5);
            ADD_FAILURE() << "maxCo 0 was accepted";
        }
        catch (const Foam::IOerror& err)
        {
            EXPECT_NE(err.message().find("'maxCo' = 0"), std::string::npos)
                << err.message();
            EXPECT_NE(err.message().find("(0, 1]"), std::string::npos)
                << err.message();
        }
        // Above the schemes' stable Courant number 1 (adv32 pr21)
        EXPECT_NO_THROW
        (
            foamTools::checkTimeControls(tc.time(), true, 1, 1e-5)
        );
        try
        {
            foamTools::checkTimeControls(tc.time(), true, 1.01, 1e-5);
            ADD_FAILURE() << "maxCo 1.01 was accepted";
        }
        catch (const Foam::IOerror& err)
        {
            EXPECT_NE
            (
                err.message().find
                (
                    "entry 'maxCo' = 1.01 is outside the valid range (0, 1]"
                ),
                std::string::npos
            ) << err.message();
        }
        // Without adjustTimeStep maxCo and maxDeltaT are not used
        EXPECT_NO_THROW(foamTools::checkTimeControls(tc.time(), false, 0, 0));
        // ... but a fixed deltaT's Courant number is at most 1 (pr22)
        EXPECT_NO_THROW(foamTools::checkCourantNumber(tc.time(), false, 1));
        EXPECT_NO_THROW(foamTools::checkCourantNumber(tc.time(), true, 3));
        try
        {
            foamTools::checkCourantNumber(tc.time(), false, 2);
            ADD_FAILURE() << "a fixed deltaT of Courant number 2 ran";
        }
        catch (const Foam::IOerror& err)
        {
            for
            (
                const std::string m :
                {
                    "entry 'deltaT' = ",
                    " s (adjustTimeStep no) gives the step from time 0 s",
                    "a Courant number of 2, above 1",
                    "Valid: deltaT <= "
                }
            )
            {
                EXPECT_NE(err.message().find(m), std::string::npos)
                    << "no '" << m << "' in: " << err.message();
            }
        }
    }
    {
        foamUnit::testCase tc("inputChecks", 0);
        try
        {
            foamTools::checkTimeControls(tc.time(), false, 0.5, 1e-5);
            ADD_FAILURE() << "deltaT 0 was accepted";
        }
        catch (const Foam::IOerror& err)
        {
            EXPECT_NE(err.message().find("'deltaT' = 0 s"), std::string::npos)
                << err.message();
        }
    }
}


namespace
{

//- A dictionary named like a case file, from text
dictionary dict(const std::string& text)
{
    IStringStream is(text);
    dictionary d(is);
    d.name() = "system/testDict";
    return d;
}

//- The message of the FatalIOError of f; fails if there is none or if it
//  does not name the file
template<class F>
std::string ioError(const F& f)
{
    try
    {
        f();
    }
    catch (const Foam::IOerror& err)
    {
        EXPECT_EQ(err.ioFileName(), "system/testDict");
        return err.message();
    }
    ADD_FAILURE() << "no FatalIOError";
    return std::string();
}

} // End anonymous namespace


TEST(inputChecks, readInRangeBounds)
{
    using foamTools::readInRange;
    const dictionary d(dict("a 0; b 1; c 0.30000000000000004; n 3;"));
    // Open lower bound excludes lo, a closed one includes it; hi included
    EXPECT_EQ(readInRange<scalar>(d, "a", "m", 0, 1, true), 0);
    EXPECT_EQ(readInRange<scalar>(d, "b", "m", 0, 1, false), 1);
    // The number as written, every digit
    EXPECT_EQ(readInRange<scalar>(d, "c", "m", 0, 1, false),
        0.30000000000000004);
    EXPECT_EQ(readInRange<label>(d, "n", "", 1, 20, true), 3);

    const std::string lo = ioError
    (
        [&]() { readInRange<scalar>(d, "a", "m", 0, 1, false); }
    );
    EXPECT_NE(lo.find("entry 'a' = 0 m is outside the valid range (0, 1] m"),
        std::string::npos) << lo;
    const std::string hi = ioError
    (
        [&]() { readInRange<scalar>(d, "b", "s", 0, 0.5, true); }
    );
    EXPECT_NE(hi.find("entry 'b' = 1 s is outside the valid range [0, 0.5]"
        " s"), std::string::npos) << hi;
    const std::string n = ioError
    (
        [&]() { readInRange<label>(d, "n", "", 4, 20, true); }
    );
    EXPECT_NE(n.find("entry 'n' = 3 is outside the valid range [4, 20]"),
        std::string::npos) << n;
    // No upper bound
    const std::string inf = ioError
    (
        [&]()
        {
            readInRange<label>
            (
                d, "a", "", 1, foamTools::noUpperBound<label>(), true
            );
        }
    );
    EXPECT_NE(inf.find("'a' = 0 is outside the valid range [1, inf)"),
        std::string::npos) << inf;
    EXPECT_EQ
    (
        readInRange<scalar>
        (
            d, "b", "m", 0, foamTools::noUpperBound<scalar>(), false
        ),
        1
    );
}


TEST(inputChecks, readInRangeBadEntries)
{
    using foamTools::readInRange;
    const dictionary d
    (
        dict("w big; two 1 2; sub { x 1; } list (1); real 2.5;")
    );
    const std::vector<std::pair<std::string, std::string>> scalars
    {
        {"missing", "missing entry 'missing' [m]"},
        {"w", "entry 'w' = 'big' is not a number [m]"},
        {"two", "entry 'two' = '1 2' is not a number [m]"},
        {"sub", "entry 'sub' is a sub-dictionary, not a number [m]"},
        {"list", "entry 'list' = '( 1 )' is not a number [m]"}
    };
    for (const auto& c : scalars)
    {
        const std::string msg = ioError
        (
            [&]() { readInRange<scalar>(d, c.first, "m", 0, 10, false); }
        );
        EXPECT_NE(msg.find(c.second), std::string::npos)
            << c.first << ": " << msg;
    }
    // A label is an integer: 2.5 is not silently cut to 2
    const std::string real = ioError
    (
        [&]() { readInRange<label>(d, "real", "steps", 0, 10, true); }
    );
    EXPECT_NE(real.find("entry 'real' = '2.5' is not an integer [steps]"),
        std::string::npos) << real;
}


TEST(inputChecks, readInRangeOrDefault)
{
    using foamTools::readInRangeOrDefault;
    const dictionary d(dict("g 20;"));
    // Missing: the default; present: read and checked
    EXPECT_EQ(readInRangeOrDefault<scalar>(d, "f", "", 1, 10, true, 1.5),
        1.5);
    EXPECT_EQ(readInRangeOrDefault<scalar>(d, "g", "", 1, 100, true, 1.5),
        20);
    const std::string msg = ioError
    (
        [&]() { readInRangeOrDefault<scalar>(d, "g", "", 1, 10, true, 1.5); }
    );
    EXPECT_NE(msg.find("entry 'g' = 20 is outside the valid range [1, 10]"),
        std::string::npos) << msg;
}


TEST(inputChecks, wholeCountAndCountAbove)
{
    // 0.007 s in steps of 1e-6 s: 7000.000000000001 as a double ratio, 7000
    // steps (adv47b f70)
    EXPECT_EQ(foamTools::wholeCount(0.007/1e-6), 7000);
    EXPECT_EQ(foamTools::wholeCount(7000.4), 7001);
    EXPECT_EQ(foamTools::wholeCount(1), 1);
    EXPECT_EQ(foamTools::wholeCount(0.5), 1);
    // printed above the limit: 3 digits, or all where those would not be
    EXPECT_EQ(foamTools::countAboveText(233, 1), "233");
    EXPECT_EQ(foamTools::countAboveText(15000000, 10000), "15000000");
    EXPECT_EQ(foamTools::countAboveText(1e24, 1e8), "1e+24");
    EXPECT_EQ(foamTools::countAboveText(1234567, 1000, 3), "1.23e+06");
    EXPECT_EQ(foamTools::countAboveText(1234567, 1234000, 3), "1234567");
    EXPECT_EQ(foamTools::countAboveText(17952, 17880), "17952");
}


TEST(inputChecks, stepCountAtTheLimit)
{
    // The run's whole steps compared with maxSteps and printed so: a
    // limit set to the count printed is accepted (adv47b f70: "about 7000
    // time steps, more than maxSteps = 7000", and the run takes 7000)
    foamUnit::testCase tc("inputChecks", 1e-6);
    Time& runTime = tc.time();
    runTime.setEndTime(0.007);
    dictionary& dict = const_cast<dictionary&>(runTime.controlDict());
    dict.set("maxSteps", 7000);
    EXPECT_NO_THROW(foamTools::checkStepCount(runTime, 1e-6, "deltaT"));
    dict.set("maxSteps", 6999);
    try
    {
        foamTools::checkStepCount(runTime, 1e-6, "deltaT");
        ADD_FAILURE() << "7000 steps ran with maxSteps 6999";
    }
    catch (const Foam::IOerror& err)
    {
        EXPECT_NE(err.message().find("about 7000 time steps, more than "
            "maxSteps = 6999"), std::string::npos) << err.message();
        EXPECT_NE(err.message().find("(valid range [1, inf))"),
            std::string::npos) << err.message();
    }
}
