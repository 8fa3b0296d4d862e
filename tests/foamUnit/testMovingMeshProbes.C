/*---------------------------------------------------------------------------*\
Description
    Unit tests of src/fsi movingMeshProbes: after every motion of the mesh
    each probe is in the cell that polyMesh::findCell (OpenFOAM's probes)
    gives it, or in a cell that holds it by findCell's own test (cells
    distorted by a third of their size overlap in their tetrahedral
    decompositions, and a point in two of them may go to either: 2 of 200
    probe positions here), both when the probes stay in their cells (the
    containment test) and when the motion carries cells past them (the
    search again); a probe outside the mesh is found nowhere.
\*---------------------------------------------------------------------------*/

#include "movingMeshProbes.H"
#include "IStringStream.H"
#include "Random.H"
#include "bitSet.H"
#include "foamTestCase.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{

//- Move the interior points of the unit-square block by up to amplitude
//  [m] in x and y, the boundary points stay
void shake(fvMesh& mesh, Random& rnd, const scalar amplitude)
{
    pointField newPoints(mesh.points());
    forAll(newPoints, p)
    {
        const point& x = mesh.points()[p];
        const bool boundary =
            x.x() < 1e-12 || x.x() > 1e-6 - 1e-12
         || x.y() < 1e-12 || x.y() > 1e-6 - 1e-12;
        if (!boundary)
        {
            newPoints[p] += 2*amplitude*vector
            (
                rnd.sample01<scalar>() - 0.5,
                rnd.sample01<scalar>() - 0.5,
                0
            );
        }
    }
    mesh.movePoints(newPoints);
}

} // End anonymous namespace


TEST(movingMeshProbes, probesAreInTheirCellsAfterEveryMotion)
{
    foamUnit::testCase tc("movingMeshProbes");
    autoPtr<fvMesh> meshPtr = tc.blockMesh
    (
        {8, 8, 1},
        [](const vector& s) { return cmptMultiply(s, vector(1e-6, 1e-6, 1e-7)); },
        {"walls", "walls", "walls", "walls", "frontAndBack", "frontAndBack"},
        {"wall", "wall", "wall", "wall", "empty", "empty"}
    );
    fvMesh& mesh = meshPtr();

    movingMeshProbes probes
    (
        "probes",
        tc.time(),
        dictionary(IStringStream
        (
            "fields (p);"
            "interpolationScheme cellPoint;"
            "probeLocations ((0.31e-6 0.52e-6 0.5e-7) (0.77e-6 0.13e-6 0.5e-7)"
            " (0.5e-6 0.9e-6 0.5e-7) (0.06e-6 0.06e-6 0.5e-7)"
            " (2e-6 0.5e-6 0.5e-7));"   // outside the mesh: never found
        )())
    );

    Random rnd(11);
    label kept = 0;
    label moved = 0;
    for (label n = 0; n < 40; ++n)
    {
        const labelList before(probes.elements());
        // Small shakes (the probes stay) alternate with large ones (cells
        // pass the probes)
        shake(mesh, rnd, (n % 2 ? 0.33 : 0.02)*1e-6/8);
        probes.movePoints(mesh);

        forAll(probes, i)
        {
            const label celli = probes.elements()[i];
            const label found = mesh.findCell(probes[i]);
            EXPECT_TRUE(celli == found || mesh.pointInCell(probes[i], celli))
                << "probe " << i << " after motion " << n << ": cell "
                << celli << ", findCell " << found;
            EXPECT_EQ(celli == -1, found == -1);
            (probes.elements()[i] == before[i] ? kept : moved)++;
        }
    }
    // Both paths ran: most probes keep their cells, some do not
    EXPECT_GT(kept, 100);
    EXPECT_GT(moved, 5);
    EXPECT_EQ(probes.elements()[4], -1);
}


// ************************************************************************* //
