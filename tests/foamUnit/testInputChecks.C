/*---------------------------------------------------------------------------*\
Description
    Unit tests of the start-up checks of src/foamTools/inputChecks.H: an
    inverted mesh and non-positive time controls are errors naming the
    cell or the entry with its valid range.

\*---------------------------------------------------------------------------*/

#include "inputChecks.H"
#include "foamTestCase.H"

#include <gtest/gtest.h>

#include <string>

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
            EXPECT_NE(err.message().find("(0, inf)"), std::string::npos)
                << err.message();
        }
        // Without adjustTimeStep maxCo and maxDeltaT are not used
        EXPECT_NO_THROW(foamTools::checkTimeControls(tc.time(), false, 0, 0));
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
