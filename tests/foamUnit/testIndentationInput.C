/*---------------------------------------------------------------------------*\
Description
    Unit tests of Foam::indentationInput (src/solidInput): the Usage
    example of its header builds the documented sphere, stepping and
    loading table, the optional entries take their defaults, the sphere
    sits on the axis above the highest point of the contact face set and
    moves with the table's depth; every kind of bad entry (missing, out of
    range, not a number, a bad row of the table, an unknown face set) is a
    FatalIOError naming the file and the entry.

\*---------------------------------------------------------------------------*/

#include "indentationInput.H"
#include "foamTestCase.H"
#include "IFstream.H"
#include "OStringStream.H"

#include "Material.H"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

using namespace Foam;

namespace
{

const char* const header =
    "FoamFile { version 2.0; format ascii; class dictionary;"
    " object indenterProperties; }\n";

//- constant/indenterProperties of the case: the header's Usage example
//  with 'edit' in place of the example's entry of the edit's keyword (a
//  keyword given twice is an error)
dictionary indenterProperties
(
    const foamUnit::testCase& tc,
    const std::string& edit = ""
)
{
    std::string text =
        header
      + foamUnit::testCase::usageExample
        (
            "src/solidInput/indentationInput.H"
        );
    if (!edit.empty())
    {
        IStringStream es(edit);
        const token key(es);
        IStringStream is(text);
        dictionary example(is);
        example.remove(key.wordToken());
        OStringStream os;
        example.write(os, false);
        text = os.str() + edit;
    }
    tc.writeFile("constant/indenterProperties", text);
    IFstream is(tc.dir()/"constant"/"indenterProperties");
    return dictionary(is);
}

//- The case's controlDict with the indentation entries
dictionary controlDict
(
    foamUnit::testCase& tc,
    const std::string& entries = "fieldWriteInterval 0.5;"
)
{
    dictionary d(tc.time().controlDict());
    IStringStream is(entries);
    d.merge(dictionary(is));
    return d;
}

//- An r-z block 10 um wide, 5 um high, one region of an incompressible
//  visco-hyperelastic material, fixed at the bottom; its top (z = 5 um)
//  is also the face set outerSurface of the Usage example
std::unique_ptr<solid::Model> block()
{
    solid::Mesh mesh(solid::Mesh::rectangle(6, 4, 0, 10e-6, 0, 5e-6));
    mesh.faceSets["outerSurface"] = mesh.faceSets.at("top");
    std::unique_ptr<solid::Model> model(new solid::Model(mesh));
    solid::MaterialParameters p;
    p.name = "solid";
    p.C10 = 100;
    p.branches = {{200, 0.5}};
    model->setMaterial("solid", solid::Material::create(p));
    model->fix("bottom", 0);
    model->fix("bottom", 1);
    model->fix("left", 0);
    return model;
}


//- The text of the FatalIOError thrown by f (empty if none)
template<class F>
std::string ioError(const F& f, fileName* file = nullptr)
{
    try
    {
        f();
    }
    catch (const Foam::IOerror& err)
    {
        if (file) *file = err.ioFileName();
        return err.message();
    }
    return std::string();
}

} // End anonymous namespace


TEST(indentationInput, usageExample)
{
    foamUnit::testCase tc("indentationInput");
    const indentationInput in(indenterProperties(tc), controlDict(tc));

    EXPECT_EQ(in.sphere().radius, 22.5e-6);
    EXPECT_EQ(in.sphere().tolerance, 1e-9);
    EXPECT_EQ(in.sphere().penaltyFactor, 10);
    EXPECT_EQ(in.contactPatch(), "outerSurface");

    const solid::IndentationSettings& s = in.settings();
    EXPECT_EQ(s.maxDepthIncrement, 0.1e-6);
    EXPECT_EQ(s.holdDeltaT0, 0.01);
    EXPECT_EQ(s.holdGrowth, 1.5);
    EXPECT_EQ(s.maxDeltaT, 5);
    EXPECT_EQ(s.forceTarget, 0.3e-9);
    EXPECT_EQ(s.forceTargetTolerance, 0.01);
    EXPECT_EQ(s.writeInterval, 0.5);
    EXPECT_EQ(s.checkpointInterval, 10);
    EXPECT_EQ(in.newton().maxCuts, 10);
    EXPECT_EQ(in.newton().log, nullptr);

    // (A load 0.3 um/s 1.41 um) (B hold 15 s) (C1 +-2 um at 10 um/s)
    // (E hold 120 s)
    const std::vector<solid::ProtocolRow>& rows = in.protocol()->rows();
    ASSERT_EQ(rows.size(), 5u);
    EXPECT_EQ(rows[0].stage, "A");
    EXPECT_EQ(rows[0].motion, "load");
    EXPECT_EQ(rows[0].rate, 0.3e-6);
    EXPECT_EQ(rows[0].amount, 1.41e-6);
    EXPECT_EQ(rows[3].motion, "unload");
    EXPECT_EQ(rows[4].stage, "E");
    EXPECT_EQ(rows[4].amount, 120);
    EXPECT_NEAR(in.protocol()->endTime(), 1.41/0.3 + 15 + 0.4 + 120, 1e-12);
    EXPECT_NEAR(in.protocol()->depth(1.41/0.3 + 15 + 0.2), 3.41e-6, 1e-18);
}


TEST(indentationInput, defaultsAndEveryDigit)
{
    foamUnit::testCase tc("indentationInput");
    const std::string required =
        "radius 1.0000000000000002e-5; tolerance 1e-9; maxDepthIncrement"
        " 1e-7; holdDeltaT0 0.01; maxDeltaT 5; protocol ((A load 1e-6"
        " 1e-6));";
    tc.writeFile("constant/indenterProperties", header + required);
    IFstream is(tc.dir()/"constant"/"indenterProperties");
    const indentationInput in
    (
        dictionary(is),
        controlDict(tc, "fieldWriteInterval 0; checkpointInterval 0;"
        " startFrom latestTime;")
    );
    // Numbers are read as numbers: the last digit of 17 counts
    EXPECT_EQ(in.sphere().radius, 1.0000000000000002e-5);
    EXPECT_NE(in.sphere().radius, 1e-5);
    EXPECT_EQ(in.sphere().penaltyFactor, 10);
    EXPECT_EQ(in.contactPatch(), "outerSurface");
    EXPECT_EQ(in.settings().holdGrowth, 1.5);
    EXPECT_EQ(in.settings().forceTarget, 0);
    EXPECT_EQ(in.settings().forceTargetTolerance, 0.01);
    EXPECT_EQ(in.settings().writeInterval, 0);
    EXPECT_EQ(in.settings().checkpointInterval, 0);
}


TEST(indentationInput, sphereAboveTheContactSet)
{
    foamUnit::testCase tc("indentationInput");
    const dictionary ip(indenterProperties(tc));
    const indentationInput in(ip, controlDict(tc));
    std::unique_ptr<solid::Model> model = block();
    const auto contact = in.addContact(*model);

    // On the axis, touching the top at depth 0, moving down (r-z: -y)
    const solid::Vec3 c0 = contact->centre(0);
    EXPECT_EQ(c0(0), 0);
    EXPECT_EQ(c0(1), 5e-6 + 22.5e-6);
    EXPECT_EQ(c0(2), 0);
    const scalar t = 1.41/0.3;
    const solid::Vec3 c = contact->centre(t);
    EXPECT_NEAR(c(1), c0(1) - in.protocol()->depth(t), 1e-18);
    EXPECT_NEAR(in.protocol()->depth(t), 1.41e-6, 1e-18);
}


TEST(indentationInput, badEntries)
{
    // Each edit appended to the Usage example, the texts its FatalIOError
    // must contain
    const std::vector<std::pair<std::string, std::vector<std::string>>>
    cases
    {
        {"radius -0.5;",
            {"entry 'radius' = -0.5 m is outside the valid range (0, 1] m"}},
        {"radius big;", {"entry 'radius' = 'big' is not a number [m]"}},
        {"radius 1 2;", {"entry 'radius' = '1 2' is not a number [m]"}},
        {"radius { value 1e-6; }", {"entry 'radius' is a sub-dictionary"}},
        {"holdGrowht 2;", {"unknown entry 'holdGrowht' in the top level;"
            " did you mean 'holdGrowth'?"}},
        {"tolerance 2;", {"entry 'tolerance' = 2 m", "(0, 1] m"}},
        // a penetration larger than a tenth of the depth step (issue 19:
        // accepted up to 1 m)
        {"tolerance 2e-8;", {"entry 'tolerance' = 2e-08 m", "(0, 1e-08] m",
            "maxDepthIncrement"}},
        {"penaltyFactor 0;", {"entry 'penaltyFactor' = 0 is", "range (0, "}},
        {"maxDepthIncrement 0;", {"'maxDepthIncrement' = 0 m", "(0, 1] m"}},
        {"holdDeltaT0 -1;", {"'holdDeltaT0' = -1 s is", "range (0, "}},
        {"maxDeltaT 2e6;", {"'maxDeltaT' = ", " s is outside the valid range"
            " (0, "}},
        {"holdGrowth 0.5;", {"'holdGrowth' = 0.5", "[1, 10]"}},
        {"forceTarget -0.5;", {"'forceTarget' = -0.5 N", "[0, 1] N"}},
        {"forceTargetTolerance 0;", {"'forceTargetTolerance' = 0", "(0, 1]"}},
        {"protocol ((A load fast 1e-6));",
            {"entry 'protocol', row 1", "(A load fast 1e-06): wrong types"}},
        {"protocol ((A load 1e-6 1e-6) (B hold 0 1 2));",
            {"entry 'protocol', row 2", "(B hold 0 1 2) has 5 items, not "
            "four\"; expected"}},
        // a hex number is two tokens (adv46b d37: "more than four items")
        {"protocol ((A load 1e-6 0x1p-22));",
            {"entry 'protocol', row 1", "(A load 1e-06 0 x1p-22) has 5 "
            "items, not four (a number written with a prefix such as 0x or"
            " a '+' sign is read as 2 tokens"}},
        {"protocol ((A load 1e-6));",
            {"entry 'protocol', row 1", "(A load 1e-06) has 3 items, not "
            "four"}},
        {"protocol (A load 1e-6 1e-6);",
            {"entry 'protocol', row 1", "a row must start with '('"}},
        {"protocol A;",
            {"entry 'protocol', row 1", "the table must start with '('"}},
        {"protocol ((A load 1e-6 1e-6) (B press 0 1));",
            {"entry 'protocol'", "row 2", "unknown motion 'press'"}},
        {"protocol ((A load -1e-6 1e-6));",
            {"entry 'protocol'", "row 1", "'rate' = -1e-06 m/s"}},
        {"protocol ((A load 1e-6 1e-6) (B unload 1e-6 2e-6));",
            {"entry 'protocol'", "row 2", "unloads to depth"}},
        // a step longer than every row of its kind: each row one step
        // (issue 19, fix19i)
        {"maxDepthIncrement 3e-6;", {"entry 'maxDepthIncrement' = 3",
            " m is longer than the longest load or unload row of entry "
            "'protocol' (1.99", "valid range (0, 1.99"}},
        {"protocol ((A load 1e-6 1e-6) (B hold 0 0.001));",
            {"entry 'holdDeltaT0' = 0.01 s is longer than the longest hold"
            " row", "(0, 0.001] s"}},
        {"maxFactorMemory 0;", {"'maxFactorMemory' = 0 B is outside the "
            "valid range (0, "}},
        {"maxFactorFlops 1e19;", {"'maxFactorFlops' = ", " flop is outside "
            "the valid range (0, "}}
    };
    for (const auto& c : cases)
    {
        foamUnit::testCase tc("indentationInput");
        fileName file;
        const std::string msg = ioError
        (
            [&]()
            {
                indentationInput
                (
                    indenterProperties(tc, c.first), controlDict(tc)
                );
            },
            &file
        );
        EXPECT_FALSE(msg.empty()) << c.first << ": accepted";
        for (const std::string& m : c.second)
        {
            EXPECT_NE(msg.find(m), std::string::npos)
                << c.first << ": no '" << m << "' in: " << msg;
        }
        EXPECT_NE(file.find("indenterProperties"), std::string::npos)
            << c.first << ": the file is not named: " << file;
    }
}


TEST(indentationInput, missingEntries)
{
    for
    (
        const std::string key
      : {"radius", "tolerance", "maxDepthIncrement", "holdDeltaT0",
         "maxDeltaT", "protocol"}
    )
    {
        foamUnit::testCase tc("indentationInput");
        dictionary d(indenterProperties(tc));
        d.remove(key);
        const std::string msg = ioError
        (
            [&]() { indentationInput(d, controlDict(tc)); }
        );
        EXPECT_NE(msg.find("missing entry '" + key + "'"), std::string::npos)
            << key << ": " << msg;
    }
}


TEST(indentationInput, badControlDict)
{
    const std::vector<std::pair<std::string, std::string>> cases
    {
        {"", "missing entry 'fieldWriteInterval' [s]"},
        {"fieldWriteInterval -1;", "'fieldWriteInterval' = -1 s"},
        {"fieldWriteInterval 0; checkpointInterval -1;",
            "'checkpointInterval' = -1 steps is outside the valid range"
            " [0, 1000000000] steps"},
        {"fieldWriteInterval 0; checkpointInterval 2.5;",
            "'checkpointInterval' = '2.5' is not an integer"},
        {"fieldWriteInterval 0; checkpointInterval often;",
            "'checkpointInterval' = 'often' is not an integer"},
        // the table starts at 0 s (issue 19: startTime 5 was accepted)
        {"fieldWriteInterval 0; startTime 5;",
            "entry 'startTime' = 5 s is outside the valid range [0, 0] s"},
        {"fieldWriteInterval 0; startTime -1e-3;",
            "entry 'startTime' = -0.001 s is outside the valid range [0, 0]"},
        {"fieldWriteInterval 0; endTime -1;",
            "entry 'endTime' = -1 s is outside the valid range"}
    };
    for (const auto& c : cases)
    {
        foamUnit::testCase tc("indentationInput");
        const std::string msg = ioError
        (
            [&]()
            {
                indentationInput
                (
                    indenterProperties(tc), controlDict(tc, c.first)
                );
            }
        );
        EXPECT_NE(msg.find(c.second), std::string::npos)
            << c.first << ": " << msg;
    }
}


TEST(indentationInput, unknownContactSet)
{
    foamUnit::testCase tc("indentationInput");
    const dictionary ip
    (
        indenterProperties(tc, "contactPatch outerSurfaces;")
    );
    const indentationInput in(ip, controlDict(tc));
    std::unique_ptr<solid::Model> model = block();
    const std::string msg = ioError([&]() { in.addContact(*model); });
    EXPECT_NE(msg.find("entry 'contactPatch'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("outerSurfaces"), std::string::npos) << msg;
}


TEST(indentationInput, factorisationAboveItsLimits)
{
    // The block's Newton matrix needs about 1e5 flop and 1e4 B (issue 19
    // sp08: a 3D mesh sat for many minutes in its first factorisation)
    for
    (
        const auto& c
      : std::vector<std::pair<std::string, std::string>>
        {
            {"maxFactorFlops 100;", "more than entry 'maxFactorFlops' = 100"
             " flop"},
            {"maxFactorMemory 100;", "more than entry 'maxFactorMemory' = 100"
             " B"}
        }
    )
    {
        foamUnit::testCase tc("indentationInput");
        const dictionary ip(indenterProperties(tc, c.first));
        const indentationInput in(ip, controlDict(tc));
        std::unique_ptr<solid::Model> model = block();
        fileName file;
        const std::string msg =
            ioError([&]() { in.addContact(*model); }, &file);
        EXPECT_NE(msg.find(c.second), std::string::npos) << msg;
        EXPECT_NE(msg.find("the cell mesh (24 elements, 35 nodes"),
            std::string::npos) << msg;
        EXPECT_NE(msg.find("valid range (0, "), std::string::npos) << msg;
        EXPECT_NE(file.find("indenterProperties"), std::string::npos) << file;
    }
}


TEST(indentationInput, factorisationFigureAcceptedAsTheLimit)
{
    // The figure a refusal prints is the estimate compared: the limit set
    // to it is accepted (adv47b f71: maxFactorMemory 1 refused "at least
    // 17880 B", then maxFactorMemory 17880 "at least 17952 B")
    for (const std::string entry : {"maxFactorMemory", "maxFactorFlops"})
    {
        std::string figure;
        {
            foamUnit::testCase tc("indentationInput");
            const dictionary ip(indenterProperties(tc, entry + " 1;"));
            const indentationInput in(ip, controlDict(tc));
            std::unique_ptr<solid::Model> model = block();
            const std::string msg =
                ioError([&]() { in.addContact(*model); });
            const std::string about("factorisation of the Newton matrix of "
                "about ");
            const auto at = msg.find(about);
            ASSERT_NE(at, std::string::npos) << msg;
            figure = msg.substr(at + about.size());
            figure = figure.substr(0, figure.find(' '));
        }
        foamUnit::testCase tc("indentationInput");
        const dictionary ip
        (
            indenterProperties(tc, entry + " " + figure + ";")
        );
        const indentationInput in(ip, controlDict(tc));
        std::unique_ptr<solid::Model> model = block();
        EXPECT_EQ(ioError([&]() { in.addContact(*model); }), "")
            << entry << " " << figure;
    }
}


TEST(indentationInput, stepFigureAcceptedAsTheLimit)
{
    // The loading table's step estimate printed is the whole table's, so
    // that maxSteps set to it is accepted (adv49a j07, adv49b i33, fix19f:
    // the sum up to the first row past the limit was printed, and maxSteps
    // raised to it was refused again, row after row)
    std::string figure;
    {
        foamUnit::testCase tc("indentationInput");
        const std::string msg = ioError
        (
            [&]()
            {
                indentationInput
                (
                    indenterProperties(tc),
                    controlDict(tc, "fieldWriteInterval 0.5; maxSteps 1;")
                );
            }
        );
        const std::string about("the loading table would take about ");
        const auto at = msg.find(about);
        ASSERT_NE(at, std::string::npos) << msg;
        figure = msg.substr(at + about.size());
        figure = figure.substr(0, figure.find(' '));
        EXPECT_NE(msg.find("more than entry 'maxSteps' = 1 "),
            std::string::npos) << msg;
    }
    foamUnit::testCase tc("indentationInput");
    EXPECT_EQ
    (
        ioError
        (
            [&]()
            {
                indentationInput
                (
                    indenterProperties(tc),
                    controlDict
                    (
                        tc, "fieldWriteInterval 0.5; maxSteps " + figure + ";"
                    )
                );
            }
        ),
        ""
    ) << "maxSteps " << figure;
}


TEST(indentationInput, sphereTooSmallForTheMesh)
{
    // The block's top faces are 10/6 um wide; the Usage example's table
    // reaches 3.41 um: a radius of 1e-12 m (contact radius 2.6e-9 m) was
    // accepted (issue 19), 22.5 um (11.9 um) is resolved
    for (const char* radius : {"radius 1e-12;", "radius 0.3e-6;"})
    {
        foamUnit::testCase tc("indentationInput");
        // the reader keeps a reference to its dictionary: kept alive here
        const dictionary ip(indenterProperties(tc, radius));
        const indentationInput in(ip, controlDict(tc));
        std::unique_ptr<solid::Model> model = block();
        fileName file;
        const std::string msg =
            ioError([&]() { in.addContact(*model); }, &file);
        EXPECT_NE(msg.find("entry 'radius' = "), std::string::npos)
            << radius << ": " << msg;
        EXPECT_NE
        (
            msg.find("outside the valid range [2.112"),
            std::string::npos
        )   << radius << ": " << msg;
        EXPECT_NE(msg.find("contact patch 'outerSurface'"), std::string::npos)
            << radius << ": " << msg;
        EXPECT_NE(file.find("indenterProperties"), std::string::npos) << file;
    }
    foamUnit::testCase tc("indentationInput");
    const dictionary ip(indenterProperties(tc));
    const indentationInput in(ip, controlDict(tc));
    std::unique_ptr<solid::Model> model = block();
    EXPECT_TRUE(ioError([&]() { in.addContact(*model); }).empty());
}
