/*---------------------------------------------------------------------------*\
Description
    Unit tests of the keyword check of our dictionaries (issue 19):
    the suggestion of the closest valid keyword (src/foamTools/
    closestKeyword.H: edit distance with adjacent swaps, the threshold
    max(2, size/3)), the refusal of an unknown keyword naming file, entry
    and suggestion, and the duplicates of one scope of one file found in
    its text (src/foamTools/keywordCheck.H): not an entry of an included
    file replaced by the text, not a duplicate in another scope, not two
    #include lines; also in a copy of a sub-dictionary and after an
    #include on the same line. A number beyond a double's range is found
    in the text (and in an included file) with its file, line and entry,
    before OpenFOAM's tokenizer traps on it (checkNumbers, inputChecks.H).

\*---------------------------------------------------------------------------*/

#include "keywordCheck.H"
#include "inputChecks.H"
#include "foamTestCase.H"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace Foam;

namespace
{

//- The message of the FatalIOError of f, "" if none
template<class F>
std::string errorOf(F f)
{
    try
    {
        f();
    }
    catch (const Foam::error& err)
    {
        const IOerror* io = dynamic_cast<const IOerror*>(&err);
        return err.message() + " file: " + (io ? io->ioFileName() : "");
    }
    return std::string();
}


//- The dictionary of file rel of the test case
dictionary readDict(const foamUnit::testCase& tc, const fileName& rel)
{
    IFstream is(tc.dir()/rel);
    return dictionary(is);
}

const std::vector<std::string> coupling
{
    "scheme", "maxIter", "tolerance", "velocityScale", "onNonConvergence"
};

} // End anonymous namespace


TEST(keywordCheck, editDistance)
{
    EXPECT_EQ(keywords::editDistance("", ""), 0u);
    EXPECT_EQ(keywords::editDistance("", "abc"), 3u);
    EXPECT_EQ(keywords::editDistance("kitten", "sitting"), 3u);
    // an adjacent swap is one edit (plain Levenshtein: 2)
    EXPECT_EQ(keywords::editDistance("tua1", "tau1"), 1u);
    EXPECT_EQ(keywords::editDistance("mapTolerence", "mapTolerance"), 1u);
    // case counts
    EXPECT_EQ(keywords::editDistance("c10", "C10"), 1u);
}


TEST(keywordCheck, closest)
{
    EXPECT_EQ(keywords::closest("maxIterr", coupling), "maxIter");
    EXPECT_EQ(keywords::closest("tolerence", coupling), "tolerance");
    EXPECT_EQ(keywords::closest("velocityscale", coupling), "velocityScale");
    // threshold max(2, size/3): 'sceme' (5) one edit, 'xyz' none close
    EXPECT_EQ(keywords::closest("sceme", coupling), "scheme");
    EXPECT_EQ(keywords::closest("xyz", coupling), "");
    // 12 characters: 4 edits are close, 5 are not
    const std::vector<std::string> v{"abcdefghijkl"};
    EXPECT_EQ(keywords::closest("abcdefghWXYZ", v), "abcdefghijkl");
    EXPECT_EQ(keywords::closest("abcdefgVWXYZ", v), "");
    // 3 characters: 2 edits are close
    EXPECT_EQ(keywords::closest("mu", {"mu1"}), "mu1");
    EXPECT_EQ(keywords::closest("Cv", {"C10"}), "C10");
    EXPECT_EQ(keywords::closest("xy", {"C10"}), "");
    // ties: the first valid one
    EXPECT_EQ(keywords::closest("ab", {"ax", "xb"}), "ax");
    EXPECT_EQ(keywords::didYouMean("maxIterr", coupling),
        "; did you mean 'maxIter'?");
    EXPECT_EQ(keywords::didYouMean("xyz", coupling), "");
}


TEST(keywordCheck, unknownKeyword)
{
    foamUnit::testCase tc("keywordCheck");
    tc.writeFile
    (
        "constant/fsiProperties",
        "FoamFile { version 2.0; format ascii; class dictionary; }\n"
        "coupling\n{\n    scheme robin;\n    maxIterr 5;\n}\n"
    );
    const dictionary top(readDict(tc, "constant/fsiProperties"));
    EXPECT_EQ(errorOf([&]{ foamTools::checkKeywords(top, {"coupling"}); }),
        "");
    const wordList valid(coupling.begin(), coupling.end());
    const std::string msg = errorOf
    (
        [&]{ foamTools::checkKeywords(top.subDict("coupling"), valid); }
    );
    for
    (
        const std::string part
      : {
            "unknown entry 'maxIterr' in 'coupling'",
            "did you mean 'maxIter'?",
            "(scheme maxIter tolerance velocityScale onNonConvergence)",
            "constant/fsiProperties"
        }
    )
    {
        EXPECT_NE(msg.find(part), std::string::npos)
            << "no \"" << part << "\" in: " << msg;
    }
    // the file the keyword is written in (fix19g, adv50b k05: was the
    // sub-dictionary's name as a file, constant/fsiProperties.coupling)
    EXPECT_EQ(msg.find("fsiProperties.coupling"), std::string::npos) << msg;
    // FoamFile is valid at the top of a file only
    EXPECT_NE(errorOf([&]{ foamTools::checkKeywords(top, {}); }), "");
}


TEST(keywordCheck, duplicates)
{
    foamUnit::testCase tc("keywordCheck");
    tc.writeFile
    (
        "constant/set",
        "nucleus { C10 13.33; d0 0; }\ncytoplasm { C10 1.6; }\n"
    );
    tc.writeFile
    (
        "constant/solidProperties",
        "FoamFile { version 2.0; format ascii; class dictionary; }\n"
        "x 1;\n"
        "materials\n"
        "{\n"
        "    #include \"set\"\n"                 // line 5
        "    nucleus { C10 20; mu1 $x; }\n"      // overrides: no duplicate
        "    #sinclude \"none.allrun\"\n"
        "    #sinclude \"none2.allrun\"\n"
        "    cytoplasm { C10 2; C10 3; }\n"      // line 9
        "}\n"
        "probes { a (1 2 3); a (1 2 3); }\n"     // line 11
    );
    const dictionary top(readDict(tc, "constant/solidProperties"));
    const dictionary& mats = top.subDict("materials");
    EXPECT_EQ(errorOf([&]{ foamTools::checkDuplicates(top); }), "");
    EXPECT_EQ(errorOf([&]{ foamTools::checkDuplicates(mats); }), "");
    EXPECT_EQ
    (
        errorOf([&]{ foamTools::checkDuplicates(mats.subDict("nucleus")); }),
        ""
    );
    // a duplicate of the scope
    const std::string msg = errorOf
    (
        [&]{ foamTools::checkDuplicates(mats.subDict("cytoplasm")); }
    );
    for
    (
        const std::string part
      : {
            "entry 'C10' is given 2 times in 'materials/cytoplasm' (lines 9"
            " and 9", "constant/solidProperties"
        }
    )
    {
        EXPECT_NE(msg.find(part), std::string::npos)
            << "no \"" << part << "\" in: " << msg;
    }
    // in a copy of the sub-dictionary (no parent, same name)
    const dictionary probes(top.subDict("probes"));
    EXPECT_NE
    (
        errorOf([&]{ foamTools::checkDuplicates(probes); })
       .find("entry 'a' is given 2 times in 'probes' (lines 11 and 11"),
        std::string::npos
    );
    // only the keys asked for
    EXPECT_EQ(errorOf([&]{ foamTools::checkDuplicates(probes, {"b"}); }), "");
    // checkKeywords checks duplicates too
    EXPECT_NE
    (
        errorOf
        (
            [&]{ foamTools::checkKeywords(mats.subDict("cytoplasm"), {"C10"}); }
        ),
        ""
    );
}


TEST(keywordCheck, duplicateAfterIncludeOnItsLine)
{
    foamUnit::testCase tc("keywordCheck");
    tc.writeFile("constant/set", "nucleus { C10 13.33; }\n");
    tc.writeFile
    (
        "constant/solidProperties",
        "materials { #include \"set\" nucleus { C10 1; C10 2; } }\n"
    );
    const dictionary top(readDict(tc, "constant/solidProperties"));
    EXPECT_NE
    (
        errorOf
        (
            [&]
            {
                foamTools::checkDuplicates
                (
                    top.subDict("materials").subDict("nucleus")
                );
            }
        ).find("entry 'C10' is given 2 times in 'materials/nucleus'"),
        std::string::npos
    );
}


TEST(keywordCheck, numbersBeyondDouble)
{
    foamUnit::testCase tc("keywordCheck");
    tc.writeFile
    (
        "constant/set",
        "// 1e999 in a comment\nnucleus\n{\n    C10 13.33;\n"
        "    mu1 (1 -1e400);\n}\n"
    );
    tc.writeFile
    (
        "constant/good",
        "/* 1e999 */ a 1e300; b \"1e999\"; c (1 -1e300); d 0e-999;\n"
        "e [0 1 -1 0 0 0 0] 1450; f inf; g 0x1p3; h 2e-300; i -0.0e-400;\n"
    );
    tc.writeFile
    (
        "constant/solidProperties",
        "materials\n{\n    #include \"set\"\n}\nradius 1e999;\n"
    );
    EXPECT_EQ
    (
        errorOf([&]{ foamTools::checkNumbers(tc.dir()/"constant/good"); }),
        ""
    );
    const std::string inc = errorOf
    (
        [&]{ foamTools::checkNumbers(tc.dir()/"constant/solidProperties"); }
    );
    for
    (
        const std::string part
      : {
            // the material's range named (fix19f: its reader's scan range)
            "entry 'mu1' = -1e400 Pa is beyond the range of a number "
            "(OpenFOAM reads |x| <= 1e+300; a double holds |x| <= 1.797",
            "the entry's valid range is (0, 1e+13) Pa: give a value in it",
            "constant/set"
        }
    )
    {
        EXPECT_NE(inc.find(part), std::string::npos)
            << "no \"" << part << "\" in: " << inc;
    }
    tc.writeFile("constant/set", "nucleus { C10 13.33; }\n");
    const std::string top = errorOf
    (
        [&]{ foamTools::checkNumbers(tc.dir()/"constant/solidProperties"); }
    );
    EXPECT_NE(top.find("entry 'radius' = 1e999"), std::string::npos) << top;
    EXPECT_NE(top.find("constant/solidProperties"), std::string::npos) << top;

    // OpenFOAM's reader: above 1e300 an error ("ill defined
    // primitiveEntry", adv30 sp18, fr36), a non-zero magnitude up to 1e-300
    // read as 0 without a word (issue 19, fix19i)
    for
    (
        const auto& c
      : std::vector<std::pair<std::string, std::string>>
        {
            {"a 1e308;", "entry 'a' = 1e308 is beyond the range of a number"},
            {"b (1 -1.7e308);", "entry 'b' = -1.7e308 is beyond the range"},
            {"c 1e-320;", "entry 'c' = 1e-320 is below the smallest "
             "magnitude OpenFOAM reads (1e-300): it would be read as 0"},
            {"d 1e-300;", "entry 'd' = 1e-300 is below the smallest"},
            {"e 1e-999;", "entry 'e' = 1e-999 is below the smallest"}
        }
    )
    {
        tc.writeFile("constant/reader", c.first + "\n");
        const std::string msg = errorOf
        (
            [&]{ foamTools::checkNumbers(tc.dir()/"constant/reader"); }
        );
        EXPECT_NE(msg.find(c.second), std::string::npos)
            << c.first << ": " << msg;
    }

    // A number below the reader: named with the entry's own range where
    // the scan holds it (system/controlDict's top level and what it
    // includes there), 0 advised only where that range holds it; else the
    // reader's limits, 0 not advised as such (adv47b f43: "give 0 or a
    // value ... in the entry's valid range" for deltaT, whose range
    // (0, inf) s refuses 0)
    for
    (
        const auto& c
      : std::vector<std::pair<std::string, std::string>>
        {
            {"deltaT 1e-300;", "entry 'deltaT' = 1e-300 s is below the "
             "smallest magnitude OpenFOAM reads (1e-300): it would be read "
             "as 0; the entry's valid range is (0, inf) s: give a value in "
             "it above 1e-300"},
            {"endTime 4.9e-324;", "entry 'endTime' = 4.9e-324 s is below "
             "the smallest magnitude OpenFOAM reads (1e-300): it would be "
             "read as 0; the entry's valid range is [0, inf) s: give 0, or "
             "a value of magnitude above 1e-300 in it"},
            {"maxSteps 1e-300;", "entry 'maxSteps' = 1e-300 is below the "
             "smallest magnitude OpenFOAM reads (1e-300): it would be read "
             "as 0; the entry's valid range is [1, inf): give a value in "
             "it"},
            {"maxCo 1e999;", "entry 'maxCo' = 1e999 is beyond the range of"
             " a number (OpenFOAM reads |x| <= 1e+300; a double holds |x| <="
             " 1.79769e+308); the entry's valid range is (0, 1]: give a "
             "value in it"},
            {"#include \"allrun\"", "entry 'deltaT' = 1e-310 s is below "
             "the smallest magnitude OpenFOAM reads (1e-300): it would be "
             "read as 0; the entry's valid range is (0, inf) s"},
            // a function object's entry: not controlDict's own
            {"functions { p { type probes; deltaT 1e-300; } }", "entry "
             "'deltaT' = 1e-300 is below the smallest magnitude OpenFOAM "
             "reads (1e-300): it would be read as 0: give a value with "
             "1e-300 < |x| <= 1e+300 in the entry's valid range (or 0, if "
             "the range holds 0)"}
        }
    )
    {
        tc.writeFile("system/allrun", "deltaT 1e-310;\n");
        tc.writeFile("system/controlDict", c.first + "\n");
        const std::string msg = errorOf
        (
            [&]{ foamTools::checkNumbers(tc.dir()/"system/controlDict"); }
        );
        EXPECT_NE(msg.find(c.second), std::string::npos)
            << c.first << ": " << msg;
        EXPECT_EQ(msg.find("give 0 or"), std::string::npos) << msg;
    }
    // OpenFOAM's reader converts to a long double and compares with 1e-300
    // before the cast: 1.0000000000000001e-300 is above and read (as the
    // double 1e-300), 1e-300 itself is read as 0 (adv48b g64, fix19f: the
    // first was refused as "below the smallest magnitude OpenFOAM reads
    // (1e-300)"); the same at the top, 1e300
    tc.writeFile
    (
        "constant/reader",
        "a 1.0000000000000001e-300;\nb -1.0000000000000001e-300;\n"
        "c 1e300;\n"
    );
    EXPECT_EQ
    (
        errorOf([&]{ foamTools::checkNumbers(tc.dir()/"constant/reader"); }),
        ""
    );
    EXPECT_EQ(foamTools::outsideReaderRange("1.0000000000000001e-300"), 0);
    EXPECT_EQ(foamTools::outsideReaderRange("1e-300"), -1);
    EXPECT_EQ(foamTools::outsideReaderRange("1.00000000000000002e-300"), -1);
    EXPECT_EQ(foamTools::outsideReaderRange("1e300"), 0);
    EXPECT_EQ(foamTools::outsideReaderRange("1.0000000000000001e300"), 1);
    EXPECT_EQ(foamTools::outsideReaderRange("1e400"), 1);

    // A dictionary whose reader registers its ranges (addScanRange): the
    // entry's range named, through includes, 0 advised only where the
    // range holds it (adv48a h08, adv48b g64, fix19f: a material's entry
    // named with the reader's limits only). Materials: solidInput.C;
    // thermo: rhoEThermoModels.C
    tc.writeFile("constant/membrane", "membrane { mu1 1e-310; }\n");
    for
    (
        const auto& c
      : std::vector<std::pair<std::pair<std::string, std::string>,
                              std::string>>
        {
            {{"solidProperties", "materials { nucleus { d0 1e-310; } }"},
             "entry 'd0' = 1e-310 1/Pa is below the smallest magnitude "
             "OpenFOAM reads (1e-300): it would be read as 0; the entry's "
             "valid range is [0, 2000) 1/Pa: give 0, or a value of "
             "magnitude above 1e-300 in it"},
            {{"solidProperties", "materials { #include \"membrane\" }"},
             "entry 'mu1' = 1e-310 Pa is below the smallest magnitude "
             "OpenFOAM reads (1e-300): it would be read as 0; the entry's "
             "valid range is (0, 1e+13) Pa: give a value in it above "
             "1e-300"},
            {{"solidProperties", "materials { cytoplasm { tau2 1e400; } }"},
             "entry 'tau2' = 1e400 s is beyond the range of a number"},
            {{"solidProperties", "materials { cytoplasm { rho0 1e999; } }"},
             "the entry's valid range is ["},
            // not a material: the reader's limits
            {{"solidProperties", "mesh { scale 1e-310; }"},
             "entry 'scale' = 1e-310 is below the smallest magnitude "
             "OpenFOAM reads (1e-300): it would be read as 0: give a value "
             "with 1e-300 < |x| <= 1e+300"},
            {{"thermophysicalProperties", "mieGruneisenCoeffs { C0 1e-310; }"},
             "entry 'C0' = 1e-310 m/s is below the smallest magnitude "
             "OpenFOAM reads (1e-300): it would be read as 0; the entry's "
             "valid range is ("},
            {{"thermophysicalProperties", "idealGasCoeffs { gamma 1e999; }"},
             "entry 'gamma' = 1e999 is beyond the range of a number"}
        }
    )
    {
        tc.writeFile("constant/" + c.first.first, c.first.second + "\n");
        const std::string msg = errorOf
        (
            [&]
            {
                foamTools::checkNumbers(tc.dir()/"constant"/c.first.first);
            }
        );
        EXPECT_NE(msg.find(c.second), std::string::npos)
            << c.first.second << ": " << msg;
    }

    // another dictionary: the reader's limits, whatever the keyword
    tc.writeFile("constant/reader", "deltaT 1e-300;\n");
    const std::string other = errorOf
    (
        [&]{ foamTools::checkNumbers(tc.dir()/"constant/reader"); }
    );
    EXPECT_NE(other.find("entry 'deltaT' = 1e-300 is below the smallest "
        "magnitude OpenFOAM reads (1e-300): it would be read as 0: give a "
        "value with 1e-300 < |x| <= 1e+300 in the entry's valid range (or "
        "0, if the range holds 0)"), std::string::npos) << other;
}


namespace
{

//- An argList of the test case (never destroyed: argList's destructor
//  ends the process, see testWriteGuard.C)
const argList& caseArgs(const foamUnit::testCase& tc)
{
    static std::string caseDir;
    caseDir = tc.dir();
    static std::vector<char*> argv;
    argv =
    {
        const_cast<char*>("foamUnitTests"),
        const_cast<char*>("-case"),
        &caseDir[0]
    };
    int argc = int(argv.size());
    char** argvp = argv.data();
    return *new argList(argc, argvp);
}

const std::string header
(
    "FoamFile { version 2.0; format ascii; class dictionary; }\n"
);

std::size_t npos()
{
    return std::string::npos;
}

//- errorOf with the line of the FatalIOError: "... file: F at line N"
template<class F>
std::string errorAtLine(F f)
{
    try
    {
        f();
    }
    catch (const Foam::IOerror& err)
    {
        return err.message() + " file: " + err.ioFileName() + " at line "
          + std::to_string(err.ioStartLineNumber());
    }
    return std::string();
}

} // End anonymous namespace


TEST(keywordCheck, duplicatesInIncludedFiles)
{
    // A keyword twice in the text of an included file is a duplicate of
    // that file (named, with its lines); a keyword of the including text
    // that replaces an included one is not; an include in another scope
    // does not count for this one
    foamUnit::testCase tc("keywordCheck");
    tc.writeFile("constant/inner", "C10 1;\nmu1 2;\n");
    tc.writeFile
    (
        "constant/set",
        "nucleus\n{\n    C10 13.33;\n    #include \"inner\"\n}\n"   // C10 in both
        "cytoplasm { C10 1.6; }\n"
    );
    tc.writeFile("constant/other", "d0 1;\nd0 2;\n");
    tc.writeFile
    (
        "constant/solidProperties",
        header
      + "materials\n{\n    #include \"set\"\n    nucleus { C10 20; }\n}\n"
        "probes { #include \"other\" }\n"
    );
    const dictionary top(readDict(tc, "constant/solidProperties"));
    const dictionary& mats = top.subDict("materials");
    EXPECT_EQ
    (
        errorOf([&]{ foamTools::checkDuplicates(mats.subDict("nucleus")); }),
        ""
    );
    EXPECT_EQ(errorOf([&]{ foamTools::checkDuplicates(mats); }), "");
    EXPECT_EQ(errorOf([&]{ foamTools::checkDuplicates(top); }), "");

    // twice in the included file, and twice in a file it includes
    tc.writeFile
    (
        "constant/set",
        "nucleus\n{\n    C10 13.33;\n    mu1 1;\n    C10 6.67;\n}\n"
    );
    const std::string msg = errorOf
    (
        [&]{ foamTools::checkDuplicates(mats.subDict("nucleus")); }
    );
    for
    (
        const std::string& part
      : {
            std::string
            (
                "entry 'C10' is given 2 times in 'materials/nucleus' of the "
                "included file "
            ),
            std::string("constant/set (lines 3 and 5"),
            "file: " + std::string(tc.dir()/"constant/set")
        }
    )
    {
        EXPECT_NE(msg.find(part), std::string::npos)
            << "no \"" << part << "\" in: " << msg;
    }
    tc.writeFile
    (
        "constant/set",
        "nucleus\n{\n    C10 13.33;\n    #include \"inner\"\n}\n"
    );
    tc.writeFile("constant/inner", "mu1 1;\ntau1 2;\nmu1 3;\n");
    EXPECT_NE
    (
        errorOf([&]{ foamTools::checkDuplicates(mats.subDict("nucleus")); })
       .find("entry 'mu1' is given 2 times in 'materials/nucleus' of the "
             "included file "),
        std::string::npos
    );
    // the included file of 'probes'
    EXPECT_NE
    (
        errorOf([&]{ foamTools::checkDuplicates(top.subDict("probes")); })
       .find("entry 'd0' is given 2 times in 'probes' of the included file"),
        std::string::npos
    );
}


TEST(keywordCheck, duplicatesThroughIncludes)
{
    // A keyword of the file given again by a file it includes after it
    // (adv36 v75, v76: the included value silently won) is a duplicate
    // naming both places; the including file giving a keyword of a set it
    // included before is the override by design, so is an Allrun's
    // options file (<dictionary>.allrun) at its end
    foamUnit::testCase tc("keywordCheck");
    tc.writeFile("constant/stepOverride", "maxDeltaT 0.05;\n");
    tc.writeFile
    (
        "constant/indenterProperties",
        header + "maxDeltaT 5;\nradius 1;\n#include \"stepOverride\"\n"
    );
    const std::string msg = errorAtLine
    (
        [&]
        {
            foamTools::checkDuplicates
            (
                readDict(tc, "constant/indenterProperties")
            );
        }
    );
    for
    (
        const std::string& part
      : {
            std::string("entry 'maxDeltaT' is given twice in the top level"),
            std::string("constant/indenterProperties line 2 and, read after"
                " it, at "),
            std::string("constant/stepOverride line 1 (included by "),
            "file: " + std::string(tc.dir()/"constant/stepOverride")
          + " at line 1"
        }
    )
    {
        EXPECT_NE(msg.find(part), npos()) << "no \"" << part << "\" in: "
            << msg;
    }
    // the same in a sub-dictionary, the include nested in another one
    tc.writeFile("constant/couplingOverride", "#include \"deeper\"\n");
    tc.writeFile("constant/deeper", "maxIter 1;\n");
    tc.writeFile
    (
        "constant/fsiProperties",
        header + "coupling\n{\n    maxIter 30;\n"
        "    #include \"couplingOverride\"\n}\n"
    );
    const dictionary fsi(readDict(tc, "constant/fsiProperties"));
    EXPECT_NE
    (
        errorOf([&]{ foamTools::checkDuplicates(fsi.subDict("coupling")); })
       .find("entry 'maxIter' is given twice in 'coupling'"),
        npos()
    );
    // by design: the file after the set it includes; an .allrun at the end
    tc.writeFile("constant/set", "nucleus { C10 1; volumetric quadratic; }\n");
    tc.writeFile("constant/solidProperties.allrun", "shearViscosity 0.5;\n");
    tc.writeFile
    (
        "constant/solidProperties",
        header + "shearViscosity 0.2;\nmaterials\n{\n    #include \"set\"\n"
        "    nucleus { volumetric mieGruneisen; }\n}\n"
        "#sinclude \"solidProperties.allrun\"\n"
    );
    const dictionary solid(readDict(tc, "constant/solidProperties"));
    EXPECT_EQ(errorOf([&]{ foamTools::checkDuplicates(solid); }), "");
    EXPECT_EQ
    (
        errorOf
        (
            [&]
            {
                foamTools::checkDuplicates
                (
                    solid.subDict("materials").subDict("nucleus")
                );
            }
        ),
        ""
    );
    // ... pulseStudy's options file too; another suffix is no options
    // file of a tool: its duplicate is refused (a user's copy included)
    tc.writeFile("constant/solidProperties.pulseStudy", "shearViscosity 0.4;\n");
    tc.writeFile("constant/solidProperties.old", "shearViscosity 0.3;\n");
    for (const std::string suffix : {"pulseStudy", "old"})
    {
        tc.writeFile
        (
            "constant/solidProperties",
            header + "shearViscosity 0.2;\n"
            "#include \"solidProperties." + suffix + "\"\n"
        );
        const std::string err
        (
            errorOf
            (
                [&]
                {
                    foamTools::checkDuplicates
                    (
                        readDict(tc, "constant/solidProperties")
                    );
                }
            )
        );
        if (suffix == "pulseStudy")
        {
            EXPECT_EQ(err, "");
        }
        else
        {
            EXPECT_NE
            (
                err.find("entry 'shearViscosity' is given twice in the top"
                    " level"),
                npos()
            ) << err;
            EXPECT_NE(err.find("constant/solidProperties.old line 1"), npos())
                << err;
        }
    }
    // the set included after the file's own entry: the set would win
    tc.writeFile
    (
        "constant/solidProperties",
        header + "materials\n{\n    nucleus { volumetric mieGruneisen; }\n"
        "    #include \"set\"\n}\n"
    );
    const dictionary late(readDict(tc, "constant/solidProperties"));
    EXPECT_NE
    (
        errorOf
        (
            [&]
            {
                foamTools::checkDuplicates
                (
                    late.subDict("materials").subDict("nucleus")
                );
            }
        ).find("entry 'volumetric' is given twice in 'materials/nucleus'"),
        npos()
    );
}


TEST(keywordCheck, duplicateOfAnIncludeInTheScopeItself)
{
    // adv52 o07: an #include standing in the scope itself gives that
    // scope's entries; the including file giving one again after it is a
    // duplicate (was: taken as an override by design, the included value
    // 0.5 replaced without a word), in fsiProperties as in every
    // dictionary the check reads; a set opening the scope itself (a
    // region's sub-dictionary) is still overridden by design
    foamUnit::testCase tc("keywordCheck");
    tc.writeFile
    (
        "constant/couplingUser",
        "// a user file of coupling settings\n\ntolerance 0.5;\n"
    );
    tc.writeFile
    (
        "constant/fsiProperties",
        header + "coupling\n{\n    #include \"couplingUser\"\n"
        "    tolerance 1e-4;\n}\n"
    );
    const dictionary fsi(readDict(tc, "constant/fsiProperties"));
    const std::string msg
    (
        errorOf([&]{ foamTools::checkDuplicates(fsi.subDict("coupling")); })
    );
    EXPECT_NE
    (
        msg.find("entry 'tolerance' is given twice in 'coupling'"), npos()
    ) << msg;
    EXPECT_NE(msg.find("constant/couplingUser line 3"), npos()) << msg;
    // "key $key;" after the include restates its value (a verification
    // tutorial's controlDict: endTime $endTime after #include
    // "riemannProblemDict"): no duplicate
    tc.writeFile("system/problem", "endTime 0.007;\nx0 0;\n");
    tc.writeFile
    (
        "system/controlDict",
        header + "#include \"problem\"\nendTime $endTime;\n"
        "deltaT 1e-7;\n"
    );
    EXPECT_EQ
    (
        errorOf
        (
            [&]{ foamTools::checkDuplicates(readDict(tc, "system/controlDict")); }
        ),
        ""
    );
    // a dictionary of its own (a FoamFile header naming another object:
    // riemannProblemDict) included, then its endTime given as a value: by
    // design (a test sets the verification case's endTime so)
    tc.writeFile
    (
        "system/riemannProblemDict",
        "FoamFile { version 2.0; format ascii; class dictionary; "
        "object riemannProblemDict; }\nendTime 0.007;\n"
    );
    tc.writeFile
    (
        "system/controlDict",
        header + "#include \"riemannProblemDict\"\nendTime 1e-8;\n"
    );
    EXPECT_EQ
    (
        errorOf
        (
            [&]{ foamTools::checkDuplicates(readDict(tc, "system/controlDict")); }
        ),
        ""
    );
    // the set's own scope opened by the set: an override by design
    tc.writeFile("constant/set", "nucleus { C10 1; }\n");
    tc.writeFile
    (
        "constant/solidProperties",
        header + "materials\n{\n    #include \"set\"\n"
        "    nucleus { C10 2; }\n}\n"
    );
    const dictionary solid(readDict(tc, "constant/solidProperties"));
    EXPECT_EQ
    (
        errorOf
        (
            [&]
            {
                foamTools::checkDuplicates
                (
                    solid.subDict("materials").subDict("nucleus")
                );
            }
        ),
        ""
    );
}


TEST(keywordCheck, duplicatesInPatternScope)
{
    // A scope named by a pattern is walked by its characters (adv36 v44:
    // a second uniformValue in the patch "(top)" was not seen)
    foamUnit::testCase tc("keywordCheck");
    tc.writeFile
    (
        "0/p",
        header + "boundaryField\n{\n    \"(top|side)\"\n    {\n"
        "        type uniformFixedValue;\n        uniformValue constant 1;\n"
        "        uniformValue constant 2;\n    }\n}\n"
    );
    EXPECT_NE
    (
        errorOf
        (
            [&]
            {
                foamTools::checkDuplicatesIn
                (
                    tc.dir()/"0/p", {"boundaryField", "(top|side)"}
                );
            }
        ).find
        (
            "entry 'uniformValue' is given 2 times in "
            "'boundaryField/(top|side)' (lines 7 and 8"
        ),
        npos()
    );
}


TEST(keywordCheck, controlDictKeywords)
{
    // OpenFOAM's keywords and the solver's are valid; a misspelt one of
    // either is refused with the closest; the entries of an included
    // dictionary of its own (a FoamFile header of another object: the
    // $endTime of system/riemannProblemDict, as the verification
    // tutorials') are not controlDict's
    foamUnit::testCase tc("keywordCheck");
    const argList& args = caseArgs(tc);
    tc.writeFile
    (
        "system/riemannProblemDict",
        "FoamFile { version 2.0; format ascii; class dictionary; "
        "object riemannProblemDict; }\n"
        "direction (1 0 0);\nx0 0;\nendTime 1e-8;\n"
    );
    const std::string good
    (
        header
      + "#include \"riemannProblemDict\"\n"
        "application rhoRiemannFoam; startFrom latestTime; startTime 0;\n"
        "stopAt endTime; endTime $endTime; deltaT 1e-12;\n"
        "writeControl adjustableRunTime; writeInterval $endTime;\n"
        "purgeWrite 0; writeFormat ascii; writePrecision 12;\n"
        "writeCompression off; timeFormat general; timePrecision 8;\n"
        "runTimeModifiable false; adjustTimeStep yes; maxCo 0.5;\n"
        "maxDeltaT 1e-9; libs (); functions { p { type probes; } }\n"
        "#sinclude \"controlDict.allrun\"\n"
    );
    const wordList ours{"adjustTimeStep", "maxCo", "maxDeltaT"};
    tc.writeFile("system/controlDict", good);
    EXPECT_EQ(errorOf([&]{ foamTools::checkControlDict(args, ours); }), "");

    std::string endTme(good);
    endTme.replace(endTme.find("endTime $endTime"), 7, "endTme");
    tc.writeFile("system/controlDict", endTme);
    const std::string msg =
        errorOf([&]{ foamTools::checkControlDict(args, ours); });
    for
    (
        const std::string part
      : {
            "unknown entry 'endTme' in the top level; did you mean 'endTime'?",
            "system/controlDict"
        }
    )
    {
        EXPECT_NE(msg.find(part), std::string::npos)
            << "no \"" << part << "\" in: " << msg;
    }

    // maxCo is not cellIndentationFoam's
    tc.writeFile("system/controlDict", good);
    EXPECT_NE
    (
        errorOf
        (
            [&]
            {
                foamTools::checkControlDict
                (
                    args, {"fieldWriteInterval", "checkpointInterval"}
                );
            }
        ).find("unknown entry 'maxCo' in the top level"),
        std::string::npos
    );

    // an included file without a header of its own holds controlDict's
    // entries: a misspelt one is refused naming it (adv53 l21: a typo in
    // controlDict.allrun or a user's "myControl" ran without a word)
    tc.writeFile("system/controlDict.allrun", "writeInteval 5e-12;\n");
    const std::string typo =
        errorOf([&]{ foamTools::checkControlDict(args, ours); });
    for
    (
        const std::string part
      : {
            "unknown entry 'writeInteval' in the top level; did you mean "
            "'writeInterval'?",
            "system/controlDict.allrun"
        }
    )
    {
        EXPECT_NE(typo.find(part), std::string::npos)
            << "no \"" << part << "\" in: " << typo;
    }

    // an #include inside a sub-dictionary gives that scope's entries, not
    // the top level's (adv53 u04 (b): a function object's probeLocations
    // from a user's file was "unknown entry 'probeLocations' in the top
    // level")
    tc.writeFile("system/controlDict.allrun", "maxCo 0.4;\n");
    tc.writeFile("system/probesUser", "probeLocations ((1e-7 1e-5 0));\n");
    std::string nested(good);
    nested.replace
    (
        nested.find("p { type probes; }"), 18,
        "p { type probes;\n    #include \"probesUser\"\n}"
    );
    tc.writeFile("system/controlDict", nested);
    EXPECT_EQ(errorOf([&]{ foamTools::checkControlDict(args, ours); }), "");
    tc.writeFile("system/controlDict", good);

    // a keyword twice in the included file of an Allrun option
    tc.writeFile("system/controlDict.allrun", "maxCo 0.4;\nmaxCo 0.3;\n");
    EXPECT_NE
    (
        errorOf([&]{ foamTools::checkControlDict(args, ours); })
       .find("entry 'maxCo' is given 2 times in the top level of the "
             "included file "),
        std::string::npos
    );
}


TEST(keywordCheck, caseNumberScan)
{
    // checkNumbers(args): every OpenFOAM file of system/, constant/, the
    // mesh and the start time directory, with the file and the line; not
    // another time, a file without FoamFile header, nor binary data
    foamUnit::testCase tc("keywordCheck");
    const argList& args = caseArgs(tc);
    const std::string controlDict
    (
        header
      + "application x; startFrom startTime; startTime 0; stopAt endTime;\n"
        "endTime 1; deltaT 1; writeControl timeStep; writeInterval 1;\n"
    );
    tc.writeFile("system/controlDict", controlDict);
    tc.writeFile
    (
        "system/fvSchemes",
        header + "laplacianSchemes\n{\n    default Gauss linear limited 1;\n}\n"
    );
    tc.writeFile("0/p", header + "internalField uniform 0;\n");
    tc.writeFile("1/p", header + "internalField uniform 1e999;\n");
    tc.writeFile("constant/notes", "radius 1e999;\n");
    tc.writeFile
    (
        "constant/polyMesh/points",
        header + "2\n(\n(0 0 0)\n(1 1 1)\n)\n"
    );
    tc.writeFile
    (
        "constant/binaryField",
        "FoamFile { version 2.0; format binary; class dictionary; }\n"
        "a 1e999;\n"
    );
    EXPECT_EQ(errorAtLine([&]{ foamTools::checkNumbers(args); }), "");

    // the start time directory: 1 with startFrom latestTime
    std::string latest(controlDict);
    latest.replace(latest.find("startTime;"), 10, "latestTime;");
    tc.writeFile("system/controlDict", latest);
    std::string msg = errorAtLine([&]{ foamTools::checkNumbers(args); });
    EXPECT_NE(msg.find("entry 'internalField' = 1e999 is beyond"), npos())
        << msg;
    EXPECT_NE(msg.find("1/p"), npos()) << msg;
    tc.writeFile("system/controlDict", controlDict);

    tc.writeFile
    (
        "system/fvSchemes",
        header + "laplacianSchemes\n{\n    default Gauss linear limited 1e999;\n}\n"
    );
    msg = errorAtLine([&]{ foamTools::checkNumbers(args); });
    for
    (
        const std::string part
      : {"entry 'default' = 1e999 is beyond", "system/fvSchemes at line 4"}
    )
    {
        EXPECT_NE(msg.find(part), npos()) << "no \"" << part << "\" in: " << msg;
    }
    tc.writeFile("system/fvSchemes", header);

    tc.writeFile
    (
        "constant/polyMesh/points",
        header + "2\n(\n(0 0 0)\n(1 -1e999 1)\n)\n"
    );
    msg = errorAtLine([&]{ foamTools::checkNumbers(args); });
    EXPECT_NE(msg.find("a value of the list = -1e999 is beyond"), npos())
        << msg;
    EXPECT_NE(msg.find("constant/polyMesh/points at line 5"), npos()) << msg;
}
