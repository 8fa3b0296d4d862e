/*---------------------------------------------------------------------------*\
Description
    Unit tests of src/fsi bandMeshMotion: two copies of a mesh take the
    same random motions of a band of points, time step after time step,
    several passes per step (as the coupling iterates), one moved by
    bandMeshMotion, the other by fvMesh::movePoints; after every pass the
    points, old points, face centres and areas, |Sf|, cell centres and
    volumes, V0, the mesh flux meshPhi (swept volumes), C, Cf and the
    interpolation factors (weights, deltaCoeffs, nonOrthDeltaCoeffs,
    nonOrthCorrectionVectors), each with its boundary values, are equal to
    the last bit. On a graded, sheared wedge (the band on the wedge sides
    and a symmetry plane, moving in r-z) and on a 3D block (the band inside
    and sliding along a wall). A band that misses one moving point (so the
    faces of that point alone) is found different.
\*---------------------------------------------------------------------------*/

#include "bandMeshMotion.H"
#include "Random.H"
#include "bitSet.H"
#include "surfaceFields.H"
#include "volFields.H"
#include "foamTestCase.H"

#include <gtest/gtest.h>

#include <functional>

using namespace Foam;

namespace
{

//- Largest |a - b| over a list of values
template<class Type>
scalar maxDiff(const UList<Type>& a, const UList<Type>& b)
{
    EXPECT_EQ(a.size(), b.size());
    scalar d = 0;
    forAll(a, i)
    {
        d = max(d, mag(a[i] - b[i]));
    }
    return d;
}


//- Largest difference of a surface field (internal and every patch)
//  relative to its largest value
template<class Type>
scalar fieldDiff
(
    const GeometricField<Type, fvsPatchField, surfaceMesh>& a,
    const GeometricField<Type, fvsPatchField, surfaceMesh>& b
)
{
    scalar d = maxDiff(a.primitiveField(), b.primitiveField());
    scalar scale = max(mag(b.primitiveField()));
    forAll(a.boundaryField(), patchi)
    {
        d = max(d, maxDiff(a.boundaryField()[patchi], b.boundaryField()[patchi]));
        if (b.boundaryField()[patchi].size())
        {
            scale = max(scale, max(mag(b.boundaryField()[patchi])));
        }
    }
    return d/max(scale, VSMALL);
}


//- Largest relative difference of the geometry the two meshes hold
//  (every quantity that fvMesh::movePoints updates), with the name of the
//  worst one
scalar geometryDifference(const fvMesh& a, const fvMesh& b, word& worst)
{
    scalar d = 0;
    auto note = [&](const word& name, const scalar di)
    {
        if (di > d || worst.empty())
        {
            d = max(d, di);
            worst = name;
        }
    };
    auto rel = [](const scalar di, const scalar scale)
    {
        return di/max(scale, VSMALL);
    };
    worst.clear();
    note("points", rel(maxDiff(a.points(), b.points()), max(mag(b.points()))));
    note
    (
        "oldPoints",
        rel(maxDiff(a.oldPoints(), b.oldPoints()), max(mag(b.oldPoints())))
    );
    note
    (
        "faceCentres",
        rel
        (
            maxDiff(a.faceCentres(), b.faceCentres()),
            max(mag(b.faceCentres()))
        )
    );
    note
    (
        "faceAreas",
        rel(maxDiff(a.faceAreas(), b.faceAreas()), max(mag(b.faceAreas())))
    );
    note
    (
        "cellCentres",
        rel
        (
            maxDiff(a.cellCentres(), b.cellCentres()),
            max(mag(b.cellCentres()))
        )
    );
    note
    (
        "cellVolumes",
        rel(maxDiff(a.cellVolumes(), b.cellVolumes()), max(b.cellVolumes()))
    );
    note("V", rel(maxDiff(a.V().field(), b.V().field()), max(b.V().field())));
    note
    (
        "V0",
        rel(maxDiff(a.V0().field(), b.V0().field()), max(b.V0().field()))
    );
    note("Sf", fieldDiff(a.Sf(), b.Sf()));
    note("magSf", fieldDiff(a.magSf(), b.magSf()));
    note("Cf", fieldDiff(a.Cf(), b.Cf()));
    note("meshPhi", fieldDiff(a.phi(), b.phi()));
    note("weights", fieldDiff(a.weights(), b.weights()));
    note("deltaCoeffs", fieldDiff(a.deltaCoeffs(), b.deltaCoeffs()));
    note
    (
        "nonOrthDeltaCoeffs",
        fieldDiff(a.nonOrthDeltaCoeffs(), b.nonOrthDeltaCoeffs())
    );
    note
    (
        "nonOrthCorrectionVectors",
        fieldDiff(a.nonOrthCorrectionVectors(), b.nonOrthCorrectionVectors())
    );
    note
    (
        "C",
        max
        (
            rel
            (
                maxDiff(a.C().primitiveField(), b.C().primitiveField()),
                max(mag(b.C().primitiveField()))
            ),
            0.0
        )
    );
    forAll(a.C().boundaryField(), patchi)
    {
        note
        (
            "C boundary",
            rel
            (
                maxDiff(a.C().boundaryField()[patchi], b.C().boundaryField()[patchi]),
                max(mag(b.faceCentres()))
            )
        );
    }
    return d;
}


//- Displacement of a band point for a random sample: the point's new
//  position
typedef std::function<point(const point&, Random&)> bandDisplacement;


//- Steps x passes random band motions of two copies of a mesh, the first
//  moved by bandMeshMotion on the band given to it, the second by
//  fvMesh::movePoints; the largest geometry difference of all passes
scalar compareMotions
(
    foamUnit::testCase& tcA,
    foamUnit::testCase& tcB,
    fvMesh& meshA,
    fvMesh& meshB,
    const labelList& moved,
    const labelList& band,
    const bandDisplacement& displace,
    word& worst
)
{
    bandMeshMotion motion(meshA, band);
    EXPECT_TRUE(motion.banded());
    EXPECT_GT(motion.nFaces(), 0);
    EXPECT_LT(motion.nCells(), meshA.nCells());

    const pointField points0(meshB.points());
    Random rnd(7);
    scalar d = 0;
    for (label step = 0; step < 4; ++step)
    {
        ++tcA.time();
        ++tcB.time();
        for (label pass = 0; pass < 3; ++pass)
        {
            pointField newPoints(points0);
            for (const label pointi : moved)
            {
                newPoints[pointi] = displace(points0[pointi], rnd);
            }
            motion.movePoints(newPoints);
            meshB.movePoints(newPoints);

            word w;
            const scalar di = geometryDifference(meshA, meshB, w);
            if (di > d)
            {
                d = di;
                worst = w;
            }
        }
    }
    return d;
}


//- The wedge's band: points with 4 um < r < 11 um, y < 5 um (the bottom
//  symmetry plane's among them)
labelList wedgeBand(const fvMesh& mesh)
{
    DynamicList<label> band;
    forAll(mesh.points(), pointi)
    {
        const point& p = mesh.points()[pointi];
        if (p.x() > 4e-6 && p.x() < 11e-6 && p.y() < 5e-6)
        {
            band.append(pointi);
        }
    }
    return labelList(band);
}


//- In r-z (here r = x, axial y), up to 0.1 um: the point stays on its
//  wedge plane; on the symmetry plane (y = 0) r only
point wedgeDisplace(const point& p, Random& rnd)
{
    const scalar dr = 0.2e-6*(rnd.sample01<scalar>() - 0.5);
    const scalar dy =
        p.y() < 1e-12 ? 0 : 0.2e-6*(rnd.sample01<scalar>() - 0.5);
    const scalar r = p.x() + dr;
    return point(r, p.y() + dy, p.z()*r/p.x());
}


//- A 3D block of 5 x 4 x 3 skewed hexahedra with a wall at y = 0
autoPtr<fvMesh> blockMesh3D(foamUnit::testCase& tc)
{
    return tc.blockMesh
    (
        {5, 4, 3},
        [](const vector& s)
        {
            return point
            (
                5e-6*s.x() + 0.5e-6*s.y()*s.z(),
                4e-6*s.y()*(1 + 0.2*s.x()),
                3e-6*s.z() + 0.3e-6*s.x()*s.y()
            );
        },
        {"sides", "sides", "wall", "sides", "sides", "sides"},
        {"patch", "patch", "wall", "patch", "patch", "patch"}
    );
}


//- The block's band: points with 1 um < x < 4 um, y < 2.5 um and
//  0.5 um < z < 2.5 um (on the wall y = 0 too)
labelList blockBand(const fvMesh& mesh)
{
    DynamicList<label> band;
    forAll(mesh.points(), pointi)
    {
        const point& p = mesh.points()[pointi];
        if
        (
            p.x() > 1e-6 && p.x() < 4e-6 && p.y() < 2.5e-6
         && p.z() > 0.5e-6 && p.z() < 2.5e-6
        )
        {
            band.append(pointi);
        }
    }
    return labelList(band);
}


//- Up to 0.1 um in every direction; on the wall (y = 0) along it
point blockDisplace(const point& p, Random& rnd)
{
    vector d = 0.2e-6*vector
    (
        rnd.sample01<scalar>() - 0.5,
        rnd.sample01<scalar>() - 0.5,
        rnd.sample01<scalar>() - 0.5
    );
    if (p.y() < 1e-12)
    {
        d.y() = 0;
    }
    return p + d;
}

} // End anonymous namespace


TEST(bandMeshMotion, wedgeEqualsMovePointsToTheLastBit)
{
    foamUnit::testCase tcA("bandMeshMotionA");
    foamUnit::testCase tcB("bandMeshMotionB");
    autoPtr<fvMesh> meshA = tcA.wedgeMesh();
    autoPtr<fvMesh> meshB = tcB.wedgeMesh();
    const labelList band(wedgeBand(meshA()));
    ASSERT_GT(band.size(), 10);

    word worst;
    const scalar d = compareMotions
    (
        tcA, tcB, meshA(), meshB(), band, band, wedgeDisplace, worst
    );
    EXPECT_EQ(d, 0) << "largest relative difference " << d << " in " << worst;
    // The motion moved the mesh
    EXPECT_GT(max(mag(meshB->phi().primitiveField())), 0);
}


TEST(bandMeshMotion, blockEqualsMovePointsToTheLastBit)
{
    foamUnit::testCase tcA("bandMeshMotionA");
    foamUnit::testCase tcB("bandMeshMotionB");
    autoPtr<fvMesh> meshA = blockMesh3D(tcA);
    autoPtr<fvMesh> meshB = blockMesh3D(tcB);
    const labelList band(blockBand(meshA()));
    ASSERT_GT(band.size(), 10);

    word worst;
    const scalar d = compareMotions
    (
        tcA, tcB, meshA(), meshB(), band, band, blockDisplace, worst
    );
    EXPECT_EQ(d, 0) << "largest relative difference " << d << " in " << worst;
    EXPECT_GT(max(mag(meshB->phi().primitiveField())), 0);
}


TEST(bandMeshMotion, aPointLeftOutOfTheBandIsFound)
{
    // The band without one point that moves: the faces of that point that
    // no other band point uses keep their old geometry
    foamUnit::testCase tcA("bandMeshMotionA");
    foamUnit::testCase tcB("bandMeshMotionB");
    autoPtr<fvMesh> meshA = blockMesh3D(tcA);
    autoPtr<fvMesh> meshB = blockMesh3D(tcB);
    const labelList moved(blockBand(meshA()));
    labelList band(moved);
    band.setSize(band.size() - 1);

    word worst;
    const scalar d = compareMotions
    (
        tcA, tcB, meshA(), meshB(), moved, band, blockDisplace, worst
    );
    EXPECT_GT(d, 1e-3) << worst;
}


TEST(bandMeshMotion, cellsWithinFaceLayersOfTheBand)
{
    // One interior point of the 5 x 4 x 3 block, the grid point (2, 2, 1):
    // the band's cells are the 2 x 2 x 2 around it, and the cells within
    // n face layers those whose grid distance |di| + |dj| + |dk| to that
    // box is at most n (counted here on the grid, not through the mesh's
    // faces; a point-neighbour stencil would count more)
    foamUnit::testCase tc("bandMeshMotionLayers");
    autoPtr<fvMesh> mesh = blockMesh3D(tc);
    const vector s(2.0/5, 2.0/4, 1.0/3);
    const point target
    (
        5e-6*s.x() + 0.5e-6*s.y()*s.z(),
        4e-6*s.y()*(1 + 0.2*s.x()),
        3e-6*s.z() + 0.3e-6*s.x()*s.y()
    );
    label nearest = -1;
    scalar dMin = GREAT;
    forAll(mesh->points(), pointi)
    {
        const scalar d = mag(mesh->points()[pointi] - target);
        if (d < dMin)
        {
            dMin = d;
            nearest = pointi;
        }
    }
    ASSERT_LT(dMin, 1e-12);

    const bandMeshMotion motion(mesh(), labelList(1, nearest));
    EXPECT_EQ(motion.nCells(), 8);

    auto gap = [](const label i, const label lo, const label hi)
    {
        return max(label(0), max(lo - i, i - hi));
    };
    for (label n = 0; n <= 7; ++n)
    {
        label expected = 0;
        for (label i = 0; i < 5; ++i)
        {
            for (label j = 0; j < 4; ++j)
            {
                for (label k = 0; k < 3; ++k)
                {
                    if (gap(i, 1, 2) + gap(j, 1, 2) + gap(k, 0, 1) <= n)
                    {
                        ++expected;
                    }
                }
            }
        }
        EXPECT_EQ(motion.nCellsWithin(n), expected) << n << " layers";
    }
    // Far enough: the whole block
    EXPECT_EQ(motion.nCellsWithin(7), mesh->nCells());
}


// ************************************************************************* //
