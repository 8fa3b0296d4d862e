/*---------------------------------------------------------------------------*\
Description
    Unit tests of src/foamTools/writeGuard.H on a case with a Time: a time
    directory carries .writeInProgress from write() until the run() that
    follows, then .writeCommitted; at a restart with startFrom latestTime,
    discardIncompleteTimes moves aside the later time directories left
    with the in-progress marker or empty (killed writes) and keeps the
    complete ones and the earliest (also when it is empty: constant, which
    findTimes lists first, is not the earliest time).

\*---------------------------------------------------------------------------*/

#include "writeGuard.H"
#include "restartLogs.H"
#include "inputRecord.H"
#include "foamTestCase.H"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

using namespace Foam;

TEST(writeGuard, markersAndDiscardOfIncompleteTimes)
{
    foamUnit::testCase tc("writeGuard");
    Time& runTime = tc.time();
    using foamTools::writeGuard;
    // The initial conditions (not written by the solver: no marker)
    tc.writeUniformField("p", dimPressure, 1e5, "zeroGradient");

    // A complete write: in progress until run(), then committed
    ++runTime;
    ASSERT_TRUE(runTime.writeTime());
    const fileName complete(runTime.timePath());
    writeGuard::write(runTime);
    EXPECT_TRUE(isFile(complete/writeGuard::inProgressName(), false));
    EXPECT_TRUE(writeGuard::incomplete(complete));
    EXPECT_TRUE(writeGuard::run(runTime));
    EXPECT_FALSE(isFile(complete/writeGuard::inProgressName(), false));
    EXPECT_TRUE(isFile(complete/writeGuard::committedName(), false));
    EXPECT_FALSE(writeGuard::incomplete(complete));

    // What a kill leaves: during a write (the in-progress marker, as
    // write() makes it), and between the creation of the directory and the
    // marker (empty)
    ++runTime;
    const fileName killed(runTime.timePath());
    mkDir(killed);
    tc.writeFile
    (
        fileName(killed.name())/writeGuard::inProgressName(),
        runTime.timeName() + "\n"
    );
    ++runTime;
    const fileName empty(runTime.timePath());
    mkDir(empty);
    EXPECT_TRUE(writeGuard::incomplete(killed));
    EXPECT_TRUE(writeGuard::incomplete(empty));

    // The restart: nothing is moved unless it starts from latestTime
    const std::string controlDict
    (
        "FoamFile { version 2.0; format ascii; class dictionary;"
        " object controlDict; }\n"
        "application foamUnitTests; startFrom startTime; startTime 0;"
        " stopAt endTime; endTime 1; deltaT 1e-6; writeControl timeStep;"
        " writeInterval 1;\n"
    );
    tc.writeFile("system/controlDict", controlDict);
    std::string caseDir(tc.dir());
    std::vector<char*> argv
    {
        const_cast<char*>("foamUnitTests"),
        const_cast<char*>("-case"),
        &caseDir[0]
    };
    int argc = int(argv.size());
    char** argvp = argv.data();
    // Never destroyed: argList's destructor ends the process
    // (UPstream::exit), which would end this test run with status 0
    const argList& args = *new argList(argc, argvp);
    EXPECT_EQ(writeGuard::discardIncompleteTimes(args), 0);
    EXPECT_TRUE(isDir(killed));

    std::string latest(controlDict);
    latest.replace(latest.find("startTime;"), 10, "latestTime;");
    tc.writeFile("system/controlDict", latest);
    EXPECT_EQ(writeGuard::discardIncompleteTimes(args), 2);
    EXPECT_TRUE(isDir(complete));
    EXPECT_TRUE(isDir(tc.dir()/"0"));
    EXPECT_FALSE(isDir(killed));
    EXPECT_FALSE(isDir(empty));
    EXPECT_TRUE(isDir(killed + ".incomplete"));
    EXPECT_TRUE(isDir(empty + ".incomplete"));
    EXPECT_EQ(TimePaths::findTimes(tc.dir()).last().name(), complete.name());
}


TEST(writeGuard, earliestTimeIsKeptBesideConstant)
{
    // findTimes lists constant first: the earliest time directory after
    // it (here an empty 0, as a case prepared by hand may have) is the
    // start of the case, never moved aside; a later empty one is
    foamUnit::testCase tc("writeGuard");
    using foamTools::writeGuard;
    ASSERT_TRUE(isDir(tc.dir()/"constant"));
    ASSERT_TRUE(isDir(tc.dir()/"0"));
    ASSERT_TRUE(writeGuard::incomplete(tc.dir()/"0"));
    mkDir(tc.dir()/"1e-06");
    tc.writeFile
    (
        "system/controlDict",
        "FoamFile { version 2.0; format ascii; class dictionary;"
        " object controlDict; }\n"
        "application foamUnitTests; startFrom latestTime; startTime 0;"
        " stopAt endTime; endTime 1; deltaT 1e-6; writeControl timeStep;"
        " writeInterval 1;\n"
    );
    std::string caseDir(tc.dir());
    std::vector<char*> argv
    {
        const_cast<char*>("foamUnitTests"),
        const_cast<char*>("-case"),
        &caseDir[0]
    };
    int argc = int(argv.size());
    char** argvp = argv.data();
    // Never destroyed (see above)
    const argList& args = *new argList(argc, argvp);
    EXPECT_EQ(writeGuard::discardIncompleteTimes(args), 1);
    EXPECT_TRUE(isDir(tc.dir()/"0"));
    EXPECT_TRUE(isDir(tc.dir()/"1e-06.incomplete"));
}


TEST(writeGuard, failedWriteIsAnError)
{
    // A file of the time that cannot be opened (here a directory in the
    // place of uniform/time: a non-writable directory does the same to a
    // user other than root) stops the run with a FatalError naming the
    // time directory. OpenFOAM's write only returns false then (and
    // skips the fields after the time dictionary), and the run went on
    // without the time, silently
    foamUnit::testCase tc("writeGuard");
    Time& runTime = tc.time();
    using foamTools::writeGuard;
    ++runTime;
    ASSERT_TRUE(runTime.writeTime());
    ASSERT_TRUE(mkDir(runTime.timePath()/"uniform"/"time"));
    std::string msg;
    try
    {
        writeGuard::write(runTime);
    }
    catch (const Foam::error& err)
    {
        msg = err.message();
    }
    for
    (
        const std::string& part
      : {
            std::string("cannot write time directory"),
            std::string(runTime.timePath()),
            std::string("a field could not be written")
        }
    )
    {
        EXPECT_NE(msg.find(part), std::string::npos)
            << "no \"" << part << "\" in: " << msg;
    }
    // not committed: moved aside at a restart
    EXPECT_TRUE(writeGuard::incomplete(runTime.timePath()));
}


// The logs' digests a commit records (restartLogs.H, logRecord): each
// commit continues the previous one's digest over the bytes added since;
// the result must be the whole file's digest, as before
TEST(writeGuard, restartLogDigestContinuesToTheWholeFile)
{
    foamUnit::testCase tc("writeGuardLogDigest");
    const fileName log(tc.time().path()/"coupling.dat");
    std::string rows("# t iterations\n");
    std::uint64_t h = 0, n = 0, hWhole = 0, nWhole = 0;
    for (int commit = 0; commit < 4; ++commit)
    {
        for (int row = 0; row < 1000*(commit + 1); ++row)
        {
            rows += std::to_string(1e-10*row) + " 3\n";
        }
        tc.writeFile("coupling.dat", rows);
        ASSERT_TRUE(foamTools::restartLogsDetail::logDigest(log, h, n));
        ASSERT_TRUE(fileDigest::whole(log, hWhole, nWhole));
        EXPECT_EQ(h, hWhole) << "commit " << commit;
        EXPECT_EQ(n, nWhole) << "commit " << commit;
        EXPECT_EQ(n, rows.size());
    }
    // It continues (not digested whole again): a byte changed among those
    // already digested is not seen by the next record ...
    rows[3] = 'T';
    rows += "1 3\n";
    tc.writeFile("coupling.dat", rows);
    ASSERT_TRUE(foamTools::restartLogsDetail::logDigest(log, h, n));
    ASSERT_TRUE(fileDigest::whole(log, hWhole, nWhole));
    EXPECT_NE(h, hWhole);
    EXPECT_EQ(n, nWhole);
    // ... and a file cut shorter than the last record is digested whole
    rows.resize(100);
    tc.writeFile("coupling.dat", rows);
    ASSERT_TRUE(foamTools::restartLogsDetail::logDigest(log, h, n));
    ASSERT_TRUE(fileDigest::whole(log, hWhole, nWhole));
    EXPECT_EQ(h, hWhole);
    EXPECT_EQ(n, 100u);
}


// A commit marker is a commit only with its record: empty (adv38 x33) or,
// for a record that says it ends with "end", cut short before that line
// (adv39 y12, y16: only the files still listed were checked); a record of
// an earlier build (no "ended") is taken as it is
TEST(writeGuard, commitMarkerCutShortIsNoCommit)
{
    foamUnit::testCase tc("writeGuardMarkerCut");
    const fileName dir(tc.dir()/"1e-09");
    const auto recorded = [&](const std::string& text)
    {
        tc.writeFile("1e-09/.writeCommitted", text);
        return foamTools::writeGuard::commitRecorded(dir);
    };
    const std::string head("1e-09\ndigest fnv1a64 ended\n");
    const std::string files("file 1a2b 10 p\nfile 3c4d 20 U\n");
    EXPECT_FALSE(recorded(""));
    EXPECT_FALSE(recorded("1e-09\n"));
    EXPECT_FALSE(recorded(head));
    EXPECT_FALSE(recorded(head + "file 1a2b 10 p\n"));
    EXPECT_FALSE(recorded(head + files + "en"));
    EXPECT_TRUE(recorded(head + files + "end\n"));
    EXPECT_TRUE(recorded(head + files + "log 5e6f 30 postProcessing/x\nend\n"));
    EXPECT_TRUE(recorded("1e-09\ndigest fnv1a64\n" + files));
    // cut inside its digest line (adv46a e01): no file line after it
    EXPECT_FALSE(recorded("1e-09\ndigest fnv1a64"));
    EXPECT_FALSE(recorded("1e-09\ndigest fnv1a64\n"));
    EXPECT_FALSE(recorded("1e-09\ndigest fnv1a64 end"));
}


// A commit marker is sealed (fix19x): a byte of it changed is a damaged
// marker, said so (adv42 g19: one bit of it flipped was "uniform/time
// changed after the run wrote it"); a marker of an earlier build (no
// seal) is not judged; a commit of the write guard seals its marker
TEST(writeGuard, damagedCommitMarkerIsSaidToBeDamaged)
{
    foamUnit::testCase tc("writeGuardMarkerSeal");
    using foamTools::writeGuard;
    const fileName marker(tc.dir()/"1e-09"/writeGuard::committedName());
    const auto damage = [&](const std::string& text)
    {
        tc.writeFile("1e-09/.writeCommitted", text);
        return writeGuard::markerDamage(marker);
    };
    const std::string body
    (
        "1e-09\ndigest fnv1a64 ended\nfile 1a2b 10 p\nfile 3c4d 20 U\n"
        "log 5e6f 30 postProcessing/fsi/0/coupling.dat\n"
    );
    const std::string sealed(body + writeGuard::sealLine(body) + "end\n");
    EXPECT_EQ(damage(sealed), "");
    EXPECT_EQ(damage(body + "end\n"), "");
    std::string flipped(sealed);
    flipped[body.find("1a2b") + 1] ^= 0x01;
    EXPECT_NE(damage(flipped).find("seal line"), std::string::npos);
    flipped = sealed;
    flipped[body.size() + 6] ^= 0x01;
    EXPECT_NE(damage(flipped).find("seal line"), std::string::npos);
    EXPECT_NE(damage(sealed + "x\n").find("'end'"), std::string::npos);
    damage(flipped);
    try
    {
        writeGuard::checkMarker(tc.dir()/"1e-09", "The restart");
        ADD_FAILURE() << "a damaged marker was taken";
    }
    catch (const Foam::error& e)
    {
        EXPECT_NE
        (
            std::string(e.message()).find("is damaged"), std::string::npos
        );
    }

    // a commit seals its marker
    Time& runTime = tc.time();
    tc.writeUniformField("p", dimPressure, 1e5, "zeroGradient");
    ++runTime;
    writeGuard::write(runTime);
    EXPECT_TRUE(writeGuard::run(runTime));
    const fileName committed(runTime.timePath()/writeGuard::committedName());
    ASSERT_TRUE(isFile(committed));
    std::ifstream is(committed.c_str());
    const std::string text
    (
        (std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>()
    );
    EXPECT_NE(text.find("\nseal "), std::string::npos);
    EXPECT_EQ(writeGuard::markerDamage(committed), "");
}


// The directory the run writes its times into removed and made again
// while it runs (OpenFOAM's decomposePar -force on the processor
// directories, adv37 w13): the next step stops with a FatalError naming
// it, before writing
TEST(writeGuard, replacedCaseDirectoryStopsTheRun)
{
    foamUnit::testCase tc("writeGuardReplaced");
    Time& runTime = tc.time();
    using foamTools::writeGuard;
    tc.writeUniformField("p", dimPressure, 1e5, "zeroGradient");
    ++runTime;
    writeGuard::write(runTime);
    EXPECT_TRUE(writeGuard::run(runTime));
    // what decomposePar -force does: the directory removed, made again
    const fileName dir(runTime.path());
    const fileName old(dir + ".old");
    ASSERT_EQ(std::rename(dir.c_str(), old.c_str()), 0);
    ASSERT_TRUE(cp(old, dir));
    ++runTime;
    std::string msg;
    try
    {
        writeGuard::write(runTime);
    }
    catch (const Foam::error& err)
    {
        msg = err.message();
    }
    for
    (
        const std::string& part
      : {
            std::string("the directory \"" + dir + "\" this run writes its"
                " times into is not the one it started in"),
            std::string("decomposePar -force")
        }
    )
    {
        EXPECT_NE(msg.find(part), std::string::npos)
            << "no \"" << part << "\" in: " << msg;
    }
    EXPECT_FALSE(isDir(runTime.timePath()));
    rmDir(old);
}


// adv47b f63 (fix19e's change, tested by fix19f): the maps of a manual
// decomposition are no input of the physics (a decomposition does not
// change the results): constant/cellDecomposition and the manual method's
// dataFile are not recorded, so that a serial run continued on ranks split
// by hand is not refused as "constant/cellDecomposition (added)"; another
// file of constant/ is
TEST(writeGuard, decompositionMapsAreNoInputsOfTheRecord)
{
    foamUnit::testCase tc("inputRecordMaps");
    const std::string header
    (
        "FoamFile { version 2.0; format ascii; class dictionary; }\n"
    );
    tc.writeFile("constant/cellDecomposition", "3(0 1 1)\n");
    tc.writeFile("constant/ranksByHand", "3(1 0 0)\n");
    tc.writeFile("constant/ranksOther", "3(1 1 0)\n");
    tc.writeFile("constant/pulse", header + "amplitude 1e6;\n");
    for
    (
        const std::string& method
      : {
            std::string("manualCoeffs { dataFile \"ranksByHand\"; }"),
            std::string("coeffs { dataFile \"ranksByHand\"; }")
        }
    )
    {
        tc.writeFile
        (
            "system/decomposeParDict",
            header + "numberOfSubdomains 2;\nmethod manual;\n" + method + "\n"
        );
        const foamTools::inputRecord record(tc.time());
        const auto& digests = record.digests();
        bool pulse = false;
        for (const auto& d : digests)
        {
            EXPECT_EQ(d.first.find("cellDecomposition"), std::string::npos)
                << method << ": " << d.first;
            EXPECT_EQ(d.first.find("ranksByHand"), std::string::npos)
                << method << ": " << d.first;
            pulse = pulse || d.first.find("constant/pulse") == 0;
        }
        EXPECT_TRUE(pulse) << method << ": constant/pulse not recorded";
        // a file of constant/ that no decomposition names is an input
        EXPECT_TRUE(digests.count("constant/ranksOther")) << method;
    }
}
