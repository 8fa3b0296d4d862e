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
    interpolationScheme cellLinearFit: exact for fields linear in space
    (in the wedge's r-z plane; in 3D) at random probe points, moved mesh
    included, and not the probe's cell value.
\*---------------------------------------------------------------------------*/

#include "movingMeshProbes.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "Random.H"
#include "bitSet.H"
#include "volFields.H"
#include "foamTestCase.H"

#include <gtest/gtest.h>

#include <functional>

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


namespace
{

//- Probes at n random points of a box (x0 + s (x1 - x0), z = 0 unless the
//  box has a z extent), cellLinearFit
movingMeshProbes fitProbes
(
    Time& runTime,
    const point& x0,
    const point& x1,
    const label n
)
{
    Random rnd(5);
    OStringStream os;
    os  << "fields (p); interpolationScheme cellLinearFit; probeLocations (";
    for (label i = 0; i < n; ++i)
    {
        const vector s
        (
            rnd.sample01<scalar>(), rnd.sample01<scalar>(),
            rnd.sample01<scalar>()
        );
        os  << point(x0 + cmptMultiply(s, x1 - x0)) << ' ';
    }
    os  << ");";
    return movingMeshProbes
    (
        "fitProbes", runTime, dictionary(IStringStream(os.str())())
    );
}


//- Largest |fit - exact| of a linear field at the probes, relative to the
//  field's spread over the mesh, and the largest |cell value - exact|
void linearFitErrors
(
    const fvMesh& mesh,
    const movingMeshProbes& probes,
    const std::function<scalar(const point&)>& f,
    scalar& fitError,
    scalar& cellError
)
{
    volScalarField p
    (
        IOobject("p", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimPressure, Zero)
    );
    forAll(p, celli)
    {
        p[celli] = f(mesh.C()[celli]);
    }
    const scalar spread = max(p.primitiveField()) - min(p.primitiveField());
    const scalarField values(probes.sampleFit(p));
    fitError = 0;
    cellError = 0;
    forAll(probes, i)
    {
        const label celli = probes.elements()[i];
        EXPECT_NE(celli, -1) << "probe " << i;
        fitError = max(fitError, mag(values[i] - f(probes[i]))/spread);
        cellError = max(cellError, mag(p[celli] - f(probes[i]))/spread);
    }
}

} // End anonymous namespace


TEST(movingMeshProbes, linearFitIsExactForLinearFieldsInAWedge)
{
    foamUnit::testCase tc("movingMeshProbes");
    autoPtr<fvMesh> mesh = tc.wedgeMesh();
    // r from 2 to 18 um, y from 0 to 8 um: probes on the mid plane z = 0
    const movingMeshProbes probes
    (
        fitProbes
        (
            tc.time(), point(2.2e-6, 0.3e-6, 0), point(17.5e-6, 7.5e-6, 0), 30
        )
    );
    // Linear in r and y (the wedge's solution directions)
    const auto f = [](const point& x)
    {
        return 1e5 + 3e11*x.x() - 7e11*x.y();
    };
    scalar fitError, cellError;
    linearFitErrors(mesh(), probes, f, fitError, cellError);
    EXPECT_LT(fitError, 1e-12);
    EXPECT_GT(cellError, 1e-2);   // the cell value is not the probe's
}


TEST(movingMeshProbes, linearFitIsExactForLinearFieldsIn3DAfterMotion)
{
    foamUnit::testCase tc("movingMeshProbes");
    autoPtr<fvMesh> meshPtr = tc.blockMesh
    (
        {6, 5, 4},
        [](const vector& s)
        {
            return point
            (
                6e-6*s.x() + 0.5e-6*s.y()*s.z(),
                5e-6*s.y()*(1 + 0.2*s.x()),
                4e-6*s.z() + 0.3e-6*s.x()*s.y()
            );
        },
        {"walls", "walls", "walls", "walls", "walls", "walls"},
        {"wall", "wall", "wall", "wall", "wall", "wall"}
    );
    fvMesh& mesh = meshPtr();
    movingMeshProbes probes
    (
        fitProbes
        (
            tc.time(), point(0.3e-6, 0.3e-6, 0.3e-6),
            point(5.5e-6, 4.5e-6, 3.5e-6), 30
        )
    );
    const auto f = [](const point& x)
    {
        return -2e5 + 3e11*x.x() + 1e11*x.y() - 4e11*x.z();
    };

    scalar fitError, cellError;
    linearFitErrors(mesh, probes, f, fitError, cellError);
    EXPECT_LT(fitError, 1e-12);
    EXPECT_GT(cellError, 1e-2);

    // The fit follows the cells when the mesh moves
    Random rnd(3);
    ++tc.time();
    pointField newPoints(mesh.points());
    forAll(newPoints, pointi)
    {
        const point& x = newPoints[pointi];
        if
        (
            x.x() > 1e-12 && x.x() < 6e-6 - 1e-12 && x.y() > 1e-12
         && x.y() < 5e-6 - 1e-12 && x.z() > 1e-12 && x.z() < 4e-6 - 1e-12
        )
        {
            newPoints[pointi] += 0.2e-6*vector
            (
                rnd.sample01<scalar>() - 0.5,
                rnd.sample01<scalar>() - 0.5,
                rnd.sample01<scalar>() - 0.5
            );
        }
    }
    mesh.movePoints(newPoints);
    probes.movePoints(mesh);
    linearFitErrors(mesh, probes, f, fitError, cellError);
    EXPECT_LT(fitError, 1e-12);
}


// ************************************************************************* //
