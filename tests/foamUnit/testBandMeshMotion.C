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
    faces of that point alone) is found different, and so is a band motion
    after the mesh was moved past bandMeshMotion if the face centres it
    keeps from its last update were taken as the step's old centres.
    Passes in which only part of the band moves, none of it, or points go
    back to the step's start, with new time steps between (the faces
    whose points kept their bits are left alone): equal to the last bit,
    the passes without a changed point counted.

    bandFaceGeometry (the face kernels of the band's update): centre,
    sweptVol, moveFace and moveQuadPair (two quadrilaterals at once, each
    lane against its own face's results) equal to face::centre and face::sweptVol, their
    face centre and area to primitiveMesh's loop, bit for bit (the
    doubles' bytes compared, so -0 against +0 counts) on random planar and
    non-planar triangles to hexagons at several scales and on degenerate
    faces (coincident and collinear points, zero area, areas below
    VSMALL, signed zeros); centreAndArea's centre is another expression
    (found different on random quadrilaterals).
\*---------------------------------------------------------------------------*/

#include "bandMeshMotion.H"
#include "bandFaceGeometry.H"
#include "Random.H"
#include "bitSet.H"
#include "surfaceFields.H"
#include "volFields.H"
#include "foamTestCase.H"

#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <memory>
#include <iomanip>
#include <sstream>

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


//- Steps of several passes in which only part of the band moves, as the
//  coupling's passes do at rest (points whose displacement is below the
//  round-off of their position keep their bits) or where the
//  displacement falls to zero: per pass each band point keeps its
//  position, moves, or goes back to the step's start, by a plan per step
//  (steps in which nothing moves after steps in which points moved, a
//  new deltaT); the first mesh moved by bandMeshMotion, the second by
//  fvMesh::movePoints. The largest geometry difference over all passes;
//  the band updates without a changed point and the faces recomputed
//  are checked against the plan
static scalar comparePartialMotions
(
    foamUnit::testCase& tcA,
    foamUnit::testCase& tcB,
    fvMesh& meshA,
    fvMesh& meshB,
    const labelList& band,
    const bandDisplacement& displace,
    word& worst
)
{
    bandMeshMotion motion(meshA, band);
    EXPECT_TRUE(motion.banded());

    // Per step: the probability that a point moves in a pass, that it
    // goes back to the step's start, and the deltaT factor
    struct stepPlan { scalar move; scalar back; scalar dtFactor; };
    const List<stepPlan> plan
    ({
        {1, 0, 1},      // the first band update: everything
        {0.5, 0, 1},    // half the band
        {0, 0, 1},      // nothing moves: last step's moved faces change
        {0, 0, 1},      // nothing at all changes
        {0, 0, 1.5},    // nothing changes, a new deltaT
        {0.3, 0.4, 1},  // some move, some go back to the step's start
        {0.05, 0, 0.5}, // a few, a new deltaT
        {0, 0, 1}
    });

    const pointField points0(meshB.points());
    pointField current(points0);
    Random rnd(5);
    scalar d = 0;
    label nUnchanged = 0;
    forAll(plan, step)
    {
        const stepPlan& sp = plan[step];
        if (sp.dtFactor != 1)
        {
            tcA.time().setDeltaT(sp.dtFactor*tcA.time().deltaTValue());
            tcB.time().setDeltaT(sp.dtFactor*tcB.time().deltaTValue());
        }
        ++tcA.time();
        ++tcB.time();
        const pointField stepStart(current);
        for (label pass = 0; pass < 3; ++pass)
        {
            bool changed = false;
            for (const label pointi : band)
            {
                const scalar r = rnd.sample01<scalar>();
                point p = current[pointi];
                if (r < sp.move)
                {
                    p = displace(points0[pointi], rnd);
                }
                else if (r < sp.move + sp.back)
                {
                    p = stepStart[pointi];
                }
                changed = changed || p != current[pointi];
                current[pointi] = p;
            }
            // (the first pass of a step after one in which points moved
            // changes their old points)
            if (!changed && !(pass == 0 && step > 0 && plan[step - 1].move))
            {
                ++nUnchanged;
            }
            motion.movePoints(current);
            meshB.movePoints(current);

            word w;
            const scalar di = geometryDifference(meshA, meshB, w);
            if (di > d)
            {
                d = di;
                worst = w;
            }
        }
    }
    // The first motion goes through fvMesh::movePoints, the other passes
    // are band updates; those the plan leaves unchanged recompute nothing
    EXPECT_EQ(motion.nUpdates(), 3*plan.size() - 1);
    EXPECT_EQ(motion.nUnchangedUpdates(), nUnchanged);
    EXPECT_GE(nUnchanged, 5);
    EXPECT_LT(motion.nFaceUpdates(), 0.6*motion.nUpdates()*motion.nFaces());
    EXPECT_GT(motion.nFaceUpdates(), 0);
    return d;
}


TEST(bandMeshMotion, partlyMovingWedgeEqualsMovePointsToTheLastBit)
{
    foamUnit::testCase tcA("bandMeshMotionA");
    foamUnit::testCase tcB("bandMeshMotionB");
    autoPtr<fvMesh> meshA = tcA.wedgeMesh();
    autoPtr<fvMesh> meshB = tcB.wedgeMesh();
    const labelList band(wedgeBand(meshA()));

    word worst;
    const scalar d = comparePartialMotions
    (
        tcA, tcB, meshA(), meshB(), band, wedgeDisplace, worst
    );
    EXPECT_EQ(d, 0) << "largest relative difference " << d << " in " << worst;
}


TEST(bandMeshMotion, partlyMovingBlockEqualsMovePointsToTheLastBit)
{
    foamUnit::testCase tcA("bandMeshMotionA");
    foamUnit::testCase tcB("bandMeshMotionB");
    autoPtr<fvMesh> meshA = blockMesh3D(tcA);
    autoPtr<fvMesh> meshB = blockMesh3D(tcB);
    const labelList band(blockBand(meshA()));

    word worst;
    const scalar d = comparePartialMotions
    (
        tcA, tcB, meshA(), meshB(), band, blockDisplace, worst
    );
    EXPECT_EQ(d, 0) << "largest relative difference " << d << " in " << worst;
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


TEST(bandMeshMotion, aMotionPastTheBandObjectIsSeen)
{
    // Step 1 banded (three passes), step 2 through fvMesh::movePoints on
    // both copies (the band object not told), step 3 banded: the old
    // centres of step 3 are those of step 2's points, not of the band
    // object's last update
    foamUnit::testCase tcA("bandMeshMotionA");
    foamUnit::testCase tcB("bandMeshMotionB");
    autoPtr<fvMesh> meshA = blockMesh3D(tcA);
    autoPtr<fvMesh> meshB = blockMesh3D(tcB);
    const labelList band(blockBand(meshA()));
    bandMeshMotion motion(meshA(), band);
    ASSERT_TRUE(motion.banded());

    const pointField points0(meshB->points());
    Random rnd(11);
    auto randomPoints = [&]()
    {
        pointField p(points0);
        for (const label pointi : band)
        {
            p[pointi] = blockDisplace(points0[pointi], rnd);
        }
        return p;
    };
    scalar d = 0;
    word worst;
    for (label step = 0; step < 3; ++step)
    {
        ++tcA.time();
        ++tcB.time();
        for (label pass = 0; pass < 3; ++pass)
        {
            const pointField p(randomPoints());
            if (step == 1)
            {
                meshA->movePoints(p);
            }
            else
            {
                motion.movePoints(p);
            }
            meshB->movePoints(p);
            word w;
            const scalar di = geometryDifference(meshA(), meshB(), w);
            if (di > d)
            {
                d = di;
                worst = w;
            }
        }
    }
    EXPECT_EQ(d, 0) << "largest relative difference " << d << " in " << worst;
}


namespace
{

//- Whether two values have the same bytes
template<class Type>
bool sameBits(const Type& a, const Type& b)
{
    return std::memcmp(&a, &b, sizeof(Type)) == 0;
}


//- A value's digits for a failure message (all 17 of a double)
std::string str(const scalar x)
{
    std::ostringstream os;
    os << std::setprecision(17) << x;
    return os.str();
}

std::string str(const vector& v)
{
    return "(" + str(v.x()) + " " + str(v.y()) + " " + str(v.z()) + ")";
}


//- A face of n points numbered from 0 over a point list
face firstPoints(const label n)
{
    face f(n);
    forAll(f, i)
    {
        f[i] = i;
    }
    return f;
}


//- Checks bandFaceGeometry against face::centre and face::sweptVol for a
//  face f over old and new points; counts the faces checked
struct faceChecker
{
    label nChecked = 0;

    void operator()
    (
        const face& f,
        const pointField& oldP,
        const pointField& newP,
        const std::string& what
    )
    {
        const point cOld = bandFaceGeometry::centre(f, oldP);
        const point cNew = bandFaceGeometry::centre(f, newP);
        EXPECT_TRUE(sameBits(cOld, f.centre(oldP)))
            << what << ": centre " << str(cOld) << " against "
            << str(f.centre(oldP));
        EXPECT_TRUE(sameBits(cNew, f.centre(newP)))
            << what << ": centre " << str(cNew) << " against "
            << str(f.centre(newP));
        const scalar sv =
            bandFaceGeometry::sweptVol(f, cOld, oldP, cNew, newP);
        const scalar svRef = f.sweptVol(oldP, newP);
        EXPECT_TRUE(sameBits(sv, svRef))
            << what << ": sweptVol " << str(sv) << " against " << str(svRef)
            << " (difference " << str(sv - svRef) << ")";
        EXPECT_TRUE
        (
            sameBits
            (
                bandFaceGeometry::sweptVolLoop(f, cOld, oldP, cNew, newP),
                svRef
            )
        ) << what << ": sweptVolLoop";

        // All at once, and the face centre and area against the general
        // loop (primitiveMesh's; a triangle's own expression otherwise)
        point cNew2;
        scalar sv2;
        vector fCtr, fArea;
        bandFaceGeometry::moveFace(f, oldP, newP, cOld, cNew2, sv2, fCtr, fArea);
        EXPECT_TRUE(sameBits(cNew2, cNew)) << what << ": moveFace centre";
        EXPECT_TRUE(sameBits(sv2, svRef)) << what << ": moveFace sweptVol";
        vector fCtrRef, fAreaRef;
        if (f.size() == 3)
        {
            fCtrRef = (1.0/3.0)*(newP[f[0]] + newP[f[1]] + newP[f[2]]);
            fAreaRef =
                0.5*((newP[f[1]] - newP[f[0]])^(newP[f[2]] - newP[f[0]]));
        }
        else
        {
            bandFaceGeometry::centreAndAreaLoop(f, newP, fCtrRef, fAreaRef);
        }
        EXPECT_TRUE(sameBits(fCtr, fCtrRef))
            << what << ": face centre " << str(fCtr) << " against "
            << str(fCtrRef);
        EXPECT_TRUE(sameBits(fArea, fAreaRef))
            << what << ": face area " << str(fArea) << " against "
            << str(fAreaRef);
        vector fCtr3, fArea3;
        bandFaceGeometry::centreAndArea(f, newP, fCtr3, fArea3);
        EXPECT_TRUE(sameBits(fCtr3, fCtrRef) && sameBits(fArea3, fAreaRef))
            << what << ": centreAndArea";
        ++nChecked;

        if (f.size() == 4)
        {
            checkPair(f, oldP, newP, cOld, cNew, svRef, fCtrRef, fAreaRef, what);
        }
    }

    //- The last quadrilateral checked and its results
    struct quad
    {
        pointField oldP, newP;
        point cOld, cNew;
        scalar swept;
        vector fCtr, fArea;
        std::string what;
    };
    std::unique_ptr<quad> last;
    label nPairs = 0;

    //- moveQuadPair on the last quadrilateral and this one (each lane
    //  against the face's own results), and on this one twice
    void checkPair
    (
        const face& f,
        const pointField& oldP,
        const pointField& newP,
        const point& cOld,
        const point& cNew,
        const scalar swept,
        const vector& fCtr,
        const vector& fArea,
        const std::string& what
    )
    {
        quad q{oldP, newP, cOld, cNew, swept, fCtr, fArea, what};
        const quad& a = last ? *last : q;
        using namespace bandFaceGeometry;
        const facePoints<4> O[2] = {{f, a.oldP}, {f, q.oldP}};
        const facePoints<4> P[2] = {{f, a.newP}, {f, q.newP}};
        const point cOlds[2] = {a.cOld, q.cOld};
        point cNews[2];
        scalar swepts[2];
        vector fCtrs[2], fAreas[2];
        moveQuadPair(O, P, cOlds, cNews, swepts, fCtrs, fAreas);
        const quad* lanes[2] = {&a, &q};
        for (label l = 0; l < 2; ++l)
        {
            const quad& r = *lanes[l];
            EXPECT_TRUE(sameBits(cNews[l], r.cNew))
                << r.what << ": moveQuadPair lane " << l << " centre "
                << str(cNews[l]) << " against " << str(r.cNew);
            EXPECT_TRUE(sameBits(swepts[l], r.swept))
                << r.what << ": moveQuadPair lane " << l << " sweptVol "
                << str(swepts[l]) << " against " << str(r.swept);
            EXPECT_TRUE(sameBits(fCtrs[l], r.fCtr))
                << r.what << ": moveQuadPair lane " << l << " face centre "
                << str(fCtrs[l]) << " against " << str(r.fCtr);
            EXPECT_TRUE(sameBits(fAreas[l], r.fArea))
                << r.what << ": moveQuadPair lane " << l << " face area "
                << str(fAreas[l]) << " against " << str(r.fArea);
        }
        last.reset(new quad(q));
        ++nPairs;
    }
};

} // End anonymous namespace


TEST(bandFaceGeometry, centreAndSweptVolAreFaceCentreAndSweptVolBitForBit)
{
    Random rnd(1912);
    faceChecker check;
    auto randomPoint = [&](const scalar scale)
    {
        return scale*vector
        (
            rnd.sample01<scalar>() - 0.5,
            rnd.sample01<scalar>() - 0.5,
            rnd.sample01<scalar>() - 0.5
        );
    };

    // Random faces: a planar polygon (points on a circle in a random
    // plane, with random radii) and a non-planar one (random points), old
    // and new positions moved by a fraction of the size, at scales of
    // 1e-7 m (the preview's cells), 1 m and 1e3 m, away from the origin
    for (label n = 3; n <= 6; ++n)
    {
        const face f(firstPoints(n));
        for (const scalar scale : {1e-7, 1.0, 1e3})
        {
            for (label sample = 0; sample < 200; ++sample)
            {
                const point origin = randomPoint(10*scale);
                const vector e1 = randomPoint(1).normalise();
                vector e2 = randomPoint(1);
                e2 = (e2 - (e2 & e1)*e1).normalise();
                pointField planar(n), skew(n);
                for (label i = 0; i < n; ++i)
                {
                    const scalar phi = constant::mathematical::twoPi*i/n;
                    const scalar r = scale*(0.5 + rnd.sample01<scalar>());
                    planar[i] =
                        origin + r*(::cos(phi)*e1 + ::sin(phi)*e2);
                    skew[i] = origin + randomPoint(scale);
                }
                for (const pointField* oldP : {&planar, &skew})
                {
                    pointField newP(*oldP);
                    for (point& p : newP)
                    {
                        p += randomPoint(0.1*scale);
                    }
                    check(f, *oldP, newP, "random n = " + std::to_string(n));
                    // Only some points move (the band's edge)
                    pointField partly(*oldP);
                    partly[0] = newP[0];
                    check(f, *oldP, partly, "one point moved");
                    // Not moving at all
                    check(f, *oldP, *oldP, "at rest");
                }
            }
        }
    }

    // Degenerate faces
    for (label n = 3; n <= 6; ++n)
    {
        const face f(firstPoints(n));
        const std::string size = " (n = " + std::to_string(n) + ")";

        // All points at one place, and at the origin with signed zeros
        pointField same(n, point(1e-6, -2e-6, 3e-6));
        check(f, same, same, "coincident points" + size);
        pointField zeros(n, point(-0.0, 0.0, -0.0));
        check(f, zeros, same, "signed zeros to coincident" + size);
        check(f, same, zeros, "coincident to signed zeros" + size);

        // Collinear points (zero area, non-zero length)
        pointField line(n);
        for (label i = 0; i < n; ++i)
        {
            line[i] = point(1e-6*i, -0.0, 2e-6*i);
        }
        pointField line2(line);
        line2[n - 1] += vector(0, 1e-7, 0);
        check(f, line, line2, "collinear to a sliver" + size);
        check(f, line2, line, "a sliver to collinear" + size);

        // Two coincident points in a regular polygon
        pointField poly(n);
        for (label i = 0; i < n; ++i)
        {
            const scalar phi = constant::mathematical::twoPi*i/n;
            poly[i] = point(::cos(phi), ::sin(phi), 0.0);
        }
        pointField pinched(poly);
        pinched[1] = pinched[0];
        check(f, poly, pinched, "two points merged" + size);

        // Areas below VSMALL (1e-300): the point average is the centre
        pointField tiny(poly);
        for (point& p : tiny)
        {
            p *= 1e-160;
        }
        check(f, tiny, poly, "area below VSMALL" + size);
        check(f, tiny, tiny, "area below VSMALL at rest" + size);

        // A face in a coordinate plane with -0 off the plane
        pointField negZero(poly);
        for (point& p : negZero)
        {
            p.z() = -0.0;
        }
        check(f, negZero, poly, "-0 off the plane" + size);
    }
    EXPECT_GT(check.nChecked, 14000);
    EXPECT_GT(check.nPairs, 3600);
}


TEST(bandFaceGeometry, theCentreIsNotTheMeshFaceCentre)
{
    // face::centre and primitiveMesh's face centre are two expressions;
    // on random non-planar quadrilaterals they differ in some bits (so the
    // swept volume's centre cannot be taken from the mesh's face centre,
    // and the comparison above can see a difference)
    Random rnd(3);
    const face f(firstPoints(4));
    label nDifferent = 0;
    for (label sample = 0; sample < 100; ++sample)
    {
        pointField p(4);
        for (point& pt : p)
        {
            pt = point
            (
                rnd.sample01<scalar>(),
                rnd.sample01<scalar>(),
                rnd.sample01<scalar>()
            );
        }
        vector fCtr, fArea;
        bandFaceGeometry::centreAndArea(f, p, fCtr, fArea);
        const point c = bandFaceGeometry::centre(f, p);
        EXPECT_LT(mag(c - fCtr), 1e-12);
        nDifferent += !sameBits(c, fCtr);
    }
    EXPECT_GT(nDifferent, 0);
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
