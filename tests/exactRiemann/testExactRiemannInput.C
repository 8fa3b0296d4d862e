/*---------------------------------------------------------------------------*\
Description
    Input of the exactRiemann sampler: the example in the Usage of
    exactRiemannInput.H parses and solves (keeps the documentation true), and
    every invalid entry is rejected naming the entry and its range.
\*---------------------------------------------------------------------------*/

#include "anyExactRiemannSolver.H"
#include "inputError.H"
#include "exactRiemannInput.H"
#include <gtest/gtest.h>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace
{

//- The \verbatim block after "Example" in exactRiemannInput.H
std::string usageExample()
{
    std::ifstream is(EXACT_RIEMANN_SOURCE_DIR "/exactRiemannInput.H");
    std::stringstream ss;
    ss << is.rdbuf();
    const std::string text = ss.str();
    const auto ex = text.find("Example");
    const auto b = text.find("\\verbatim", ex);
    const auto e = text.find("\\endverbatim", b);
    if (ex == std::string::npos || e == std::string::npos) return "";
    return text.substr(b + 9, e - b - 9);
}

riemann::exactRiemannInput::entryTable exampleEntries()
{
    riemann::exactRiemannInput::entryTable entries;
    std::istringstream is(usageExample());
    riemann::exactRiemannInput::read(is, "exactRiemannInput.H", entries);
    return entries;
}

//- The what() of the inputError thrown for the entries
std::string errorFor(const riemann::exactRiemannInput::entryTable& entries)
{
    try
    {
        riemann::exactRiemannInput rc(entries);
    }
    catch (const riemann::inputError& err)
    {
        return err.what();
    }
    return "no error";
}

} // namespace


TEST(exactRiemannInput, usageExampleParsesAndSolves)
{
    const auto entries = exampleEntries();
    ASSERT_EQ(entries.size(), 18u);
    const riemann::exactRiemannInput rc(entries);
    EXPECT_EQ(riemann::eosName(rc.law()), "mieGruneisen");
    EXPECT_EQ(rc.points().size(), 201u);
    EXPECT_DOUBLE_EQ(rc.left().p, 1e9);
    // Both states are cold water (e = 0) as the comment says
    const auto& law = std::get<eos::MieGruneisen>(rc.law());
    EXPECT_NEAR(law.e(rc.left().rho, rc.left().p), 0, 10.0);
    EXPECT_NEAR(law.e(rc.right().rho, rc.right().p), 0, 10.0);
    const riemann::anyExactRiemannSolver rp(rc.law(), rc.left(), rc.right());
    EXPECT_GT(rp.star().p, 1e8);
}


TEST(exactRiemannInput, invalidEntriesNameTheEntryAndRange)
{
    auto with = [](const std::string& key, const std::string& value)
    {
        auto e = exampleEntries();
        e[key] = value;
        return e;
    };
    auto contains = [](const std::string& s, const std::string& part)
    {
        return s.find(part) != std::string::npos;
    };
    std::string m;
    m = errorFor(with("rhoL", "-1"));
    EXPECT_TRUE(contains(m, "'rhoL'") && contains(m, "kg/m^3")) << m;
    m = errorFor(with("t", "0"));
    EXPECT_TRUE(contains(m, "'t'") && contains(m, "(0, inf)")) << m;
    m = errorFor(with("pR", "abc"));
    EXPECT_TRUE(contains(m, "'pR'") && contains(m, "not a number")) << m;
    m = errorFor(with("n", "2.5"));
    EXPECT_TRUE(contains(m, "'n'") && contains(m, "integer")) << m;
    m = errorFor(with("n", "1"));
    EXPECT_TRUE(contains(m, "'n'")) << m;
    m = errorFor(with("xMax", "-1"));
    EXPECT_TRUE(contains(m, "'xMax'")) << m;
    m = errorFor(with("uL", "nan"));
    EXPECT_TRUE(contains(m, "'uL'")) << m;
    m = errorFor(with("pressure", "1"));
    EXPECT_TRUE(contains(m, "unknown entry 'pressure'")) << m;
    m = errorFor(with("gamma", "1.4"));
    EXPECT_TRUE(contains(m, "unknown entry 'gamma'")) << m;
    // a misspelt entry names the closest valid one (issue 19)
    m = errorFor(with("rhoLL", "1000"));
    EXPECT_TRUE(contains(m, "unknown entry 'rhoLL'; did you mean 'rhoL'?"))
        << m;
    m = errorFor(with("law", "tillotson"));
    EXPECT_TRUE(contains(m, "mieGruneisen") && contains(m, "idealGas")) << m;
    auto missing = exampleEntries();
    missing.erase("pL");
    m = errorFor(missing);
    EXPECT_TRUE(contains(m, "missing entry 'pL'")) << m;
    EXPECT_THROW
    (
        riemann::exactRiemannInput(with("C0", "-1450")), eos::ParameterError
    );
}


TEST(exactRiemannInput, argumentsOverrideAndMalformedLinesAreRejected)
{
    auto entries = exampleEntries();
    riemann::exactRiemannInput::readArgument("t=2e-5", entries);
    EXPECT_DOUBLE_EQ(riemann::exactRiemannInput(entries).t(), 2e-5);
    EXPECT_THROW
    (
        riemann::exactRiemannInput::readArgument("t2e-5", entries),
        riemann::inputError
    );
    std::istringstream bad("rhoL 1 2;\n");
    EXPECT_THROW
    (
        riemann::exactRiemannInput::read(bad, "bad", entries),
        riemann::inputError
    );
    // a key twice in one file is an error (the last won silently)
    std::istringstream twice("rhoL 1;\nuL 0; rhoL 2;\n");
    try
    {
        riemann::exactRiemannInput::read(twice, "twice", entries);
        ADD_FAILURE() << "a key given twice was accepted";
    }
    catch (const riemann::inputError& err)
    {
        EXPECT_NE
        (
            std::string(err.what()).find
            (
                "twice:2: entry 'rhoL' is given twice (first on line 1)"
            ),
            std::string::npos
        ) << err.what();
    }
}


// adv52 p10, p27 (issue 19): a key given twice as an argument (the later
// replaced the earlier without a word) and a byte-order mark at the case
// file's start (taken into the first key: "missing entry 'law'") are named
TEST(exactRiemannInput, argumentTwiceAndByteOrderMarkAreNamed)
{
    auto entries = exampleEntries();
    std::set<std::string> given;
    riemann::exactRiemannInput::readArgument("rhoL=1000", entries, given);
    // the case file's key replaced by an argument: on purpose, accepted
    riemann::exactRiemannInput::readArgument("t=2e-5", entries, given);
    try
    {
        riemann::exactRiemannInput::readArgument("rhoL=998", entries, given);
        ADD_FAILURE() << "an argument's key given twice was accepted";
    }
    catch (const riemann::inputError& err)
    {
        EXPECT_NE
        (
            std::string(err.what()).find
            (
                "the key 'rhoL' is given twice as an argument"
            ),
            std::string::npos
        ) << err.what();
    }
    std::istringstream bom("\xEF\xBB\xBFlaw stiffenedGas;\n");
    try
    {
        riemann::exactRiemannInput::read(bom, "bom.case", entries);
        ADD_FAILURE() << "a byte-order mark was taken into the first key";
    }
    catch (const riemann::inputError& err)
    {
        EXPECT_NE
        (
            std::string(err.what()).find
            (
                "bom.case:1: the file starts with a UTF-8 byte-order mark"
            ),
            std::string::npos
        ) << err.what();
    }
}
