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
    interpolationScheme cellPoint, and localCellPoint alone: equal to the
    whole-field interpolation (interpolationCellPoint, volPointInterpolation)
    to the last bit on a moving wedge and a moving skewed 3D block, for
    scalar fields everywhere and vector fields off constraint patches, both
    kinds of point weights (cells, boundary faces) used; the whole-field
    path where localCellPoint is not exact.
\*---------------------------------------------------------------------------*/

#include "movingMeshProbes.H"
#include "localCellPoint.H"
#include "scaleFreeCellPointWeight.H"
#include "interpolationCellPoint.H"
#include "wedgePolyPatch.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "Random.H"
#include "bitSet.H"
#include "volFields.H"
#include "foamTestCase.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
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


//- The 6 x 5 x 4 um block of the 3D tests, its lines curved and skewed
//  (s in [0, 1]^3)
static point skewedBlock(const vector& s)
{
    return point
    (
        6e-6*s.x() + 0.5e-6*s.y()*s.z(),
        5e-6*s.y()*(1 + 0.2*s.x()),
        4e-6*s.z() + 0.3e-6*s.x()*s.y()
    );
}


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
        skewedBlock,
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


namespace
{

//- A smooth, non-linear field value at x [m] (its boundary values differ
//  from the cells' by offset, so that the boundary points' weights count)
template<class Type>
Type smooth(const point& x, const scalar offset);

template<>
scalar smooth(const point& x, const scalar offset)
{
    const vector s(x/1e-6);
    return
        1e5
       *(1 + offset + 0.3*std::sin(s.x()) + 0.2*s.y()*s.y() - 0.1*s.z());
}

template<>
vector smooth(const point& x, const scalar offset)
{
    const vector s(x/1e-6);
    return vector
    (
        std::cos(s.y()) + offset,
        0.1*s.x()*s.z() - offset,
        std::sin(s.x() + s.y()) + 2*offset
    );
}


//- A vol field of smooth values in the cells and on every patch
template<class Type>
tmp<GeometricField<Type, fvPatchField, volMesh>> smoothField
(
    const fvMesh& mesh,
    const word& name
)
{
    typedef GeometricField<Type, fvPatchField, volMesh> fieldType;
    tmp<fieldType> tvf
    (
        new fieldType
        (
            IOobject(name, mesh.time().timeName(), mesh),
            mesh,
            dimensioned<Type>(dimless, Zero)
        )
    );
    fieldType& vf = tvf.ref();
    forAll(vf, celli)
    {
        vf[celli] = smooth<Type>(mesh.C()[celli], 0);
    }
    typename fieldType::Boundary& bf = vf.boundaryFieldRef();
    forAll(bf, patchi)
    {
        const vectorField& Cf = mesh.boundary()[patchi].Cf();
        Field<Type> values(Cf.size());
        forAll(Cf, facei)
        {
            values[facei] = smooth<Type>(Cf[facei], 0.05 + 0.01*patchi);
        }
        bf[patchi] == values;
    }
    return tvf;
}


//- n random positions in the box x0 + s (x1 - x0) (z = x0.z() if the box is
//  flat in z)
List<point> randomPoints
(
    const point& x0,
    const point& x1,
    const label n,
    const label seed
)
{
    Random rnd(seed);
    List<point> points(n);
    for (point& x : points)
    {
        const vector s
        (
            rnd.sample01<scalar>(), rnd.sample01<scalar>(),
            rnd.sample01<scalar>()
        );
        x = x0 + cmptMultiply(s, x1 - x0);
    }
    return points;
}


//- Move every point that lies on no boundary by up to amplitude [m]
//  in each direction of the mesh
void shakeInterior(fvMesh& mesh, Random& rnd, const scalar amplitude)
{
    bitSet onBoundary(mesh.nPoints());
    for (label facei = mesh.nInternalFaces(); facei < mesh.nFaces(); ++facei)
    {
        onBoundary.set(mesh.faces()[facei]);
    }
    pointField newPoints(mesh.points());
    forAll(newPoints, pointi)
    {
        if (!onBoundary.test(pointi))
        {
            newPoints[pointi] += 2*amplitude*vector
            (
                rnd.sample01<scalar>() - 0.5,
                rnd.sample01<scalar>() - 0.5,
                rnd.sample01<scalar>() - 0.5
            );
        }
    }
    mesh.movePoints(newPoints);
}


//- Move the wedge's points that lie on no boundary but its sides by up to
//  amplitude [m] in r (= x) and y, each pair on the two sides alike (a
//  smooth motion of random phases), keeping them on their sides
void shakeWedge(fvMesh& mesh, Random& rnd, const scalar amplitude)
{
    const polyBoundaryMesh& pbm = mesh.boundaryMesh();
    bitSet fixed(mesh.nPoints());
    for (label facei = mesh.nInternalFaces(); facei < mesh.nFaces(); ++facei)
    {
        if (!isA<wedgePolyPatch>(pbm[pbm.whichPatch(facei)]))
        {
            fixed.set(mesh.faces()[facei]);
        }
    }
    const scalar phaseR = 6.3*rnd.sample01<scalar>();
    const scalar phaseY = 6.3*rnd.sample01<scalar>();
    pointField newPoints(mesh.points());
    forAll(newPoints, pointi)
    {
        if (!fixed.test(pointi))
        {
            const point& x = newPoints[pointi];
            const scalar r = x.x() + amplitude*std::sin(1.7e6*x.y() + phaseR);
            const scalar y = x.y() + amplitude*std::cos(0.9e6*x.x() + phaseY);
            newPoints[pointi] = point(r, y, x.z()*r/x.x());
        }
    }
    mesh.movePoints(newPoints);
}


//- An OpenFOAM value as text (for the messages of failed checks)
template<class Type>
std::string text(const Type& x)
{
    OStringStream os;
    os.precision(17);
    os  << x;
    return os.str();
}


//- Whether a and b are the same bits
template<class Type>
bool sameBits(const Type& a, const Type& b)
{
    return std::memcmp(&a, &b, sizeof(Type)) == 0;
}


//- For each position: localCellPoint's value where it is exact, and
//  interpolationCellPoint's (the whole field's point values) to the last
//  bit; returns the number of exact positions, counts the tetrahedra's
//  vertices with boundary weights (on a patch) and with cell weights
template<class Type>
label checkLocalCellPoint
(
    const fvMesh& mesh,
    const List<point>& positions,
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    label& patchVertices,
    label& cellVertices
)
{
    const localCellPoint local(mesh);
    interpolationCellPoint<Type> whole(vf);
    label nExact = 0;
    for (const point& x : positions)
    {
        const label celli = mesh.findCell(x);
        if (celli == -1)
        {
            continue;
        }
        const scaleFreeCellPointWeight cpw(mesh, x, celli);
        if (!local.exact<Type>(cpw))
        {
            continue;
        }
        ++nExact;
        const Type value = local.interpolate(vf, cpw);
        const Type reference = whole.interpolate(cpw.weights(), cpw.tet());
        EXPECT_TRUE(sameBits(value, reference))
            << "at " << text(x) << " in cell " << celli << ": "
            << text(value) << " against " << text(reference)
            << " (difference " << text(value - reference) << ")";
        for (const label pointi : cpw.faceVertices())
        {
            bool onPatch = false;
            for (const label facei : mesh.pointFaces()[pointi])
            {
                onPatch = onPatch || !mesh.isInternalFace(facei);
            }
            (onPatch ? patchVertices : cellVertices)++;
        }
    }
    return nExact;
}

} // End anonymous namespace


TEST(localCellPoint, equalsTheWholeFieldInterpolationInAMovingWedge)
{
    foamUnit::testCase tc("localCellPoint");
    autoPtr<fvMesh> meshPtr = tc.wedgeMesh();
    fvMesh& mesh = meshPtr();
    // On the wedge's mid plane, bottom (symmetryPlane) to top, inner to
    // outer
    const List<point> positions
    (
        randomPoints
        (
            point(2.01e-6, 0.01e-6, 0), point(17.99e-6, 7.99e-6, 0), 80, 7
        )
    );

    Random rnd(13);
    label patchVertices = 0;
    label cellVertices = 0;
    for (label n = 0; n < 4; ++n)
    {
        if (n)
        {
            ++tc.time();
            shakeWedge(mesh, rnd, 0.3e-6);
        }
        const tmp<volScalarField> p(smoothField<scalar>(mesh, "p"));
        // Scalars: exact everywhere (the wedge sides and the symmetry plane
        // leave a scalar point value as it is)
        EXPECT_EQ
        (
            checkLocalCellPoint
            (
                mesh, positions, p(), patchVertices, cellVertices
            ),
            positions.size()
        );

        // Vectors: every point is on a wedge side, whose constraint
        // transforms a vector: never exact
        const tmp<volVectorField> U(smoothField<vector>(mesh, "U"));
        label unused = 0;
        EXPECT_EQ
        (
            checkLocalCellPoint(mesh, positions, U(), unused, unused), 0
        );
    }
    // Every point of a wedge is on its sides: boundary weights only
    EXPECT_EQ(patchVertices, 3*4*positions.size());
    EXPECT_EQ(cellVertices, 0);
}


TEST(localCellPoint, equalsTheWholeFieldInterpolationInAMoving3DBlock)
{
    foamUnit::testCase tc("localCellPoint");
    autoPtr<fvMesh> meshPtr = tc.blockMesh
    (
        {6, 5, 4},
        skewedBlock,
        {"inlet", "walls", "symmetry", "walls", "walls", "walls"},
        {"patch", "wall", "symmetryPlane", "wall", "wall", "wall"}
    );
    fvMesh& mesh = meshPtr();
    const List<point> positions
    (
        randomPoints
        (
            point(0.01e-6, 0.01e-6, 0.01e-6),
            point(5.99e-6, 4.99e-6, 3.99e-6),
            150,
            3
        )
    );

    Random rnd(17);
    label patchVertices = 0;
    label cellVertices = 0;
    label vectorPatchVertices = 0;
    label vectorCellVertices = 0;
    label nScalar = 0;
    label nVector = 0;
    for (label n = 0; n < 4; ++n)
    {
        if (n)
        {
            ++tc.time();
            shakeInterior(mesh, rnd, 0.15e-6);
        }
        const tmp<volScalarField> p(smoothField<scalar>(mesh, "p"));
        nScalar += checkLocalCellPoint
        (
            mesh, positions, p(), patchVertices, cellVertices
        );
        // Vectors: exact off the symmetry plane (on the walls and the
        // inlet the point values need no constraint)
        const tmp<volVectorField> U(smoothField<vector>(mesh, "U"));
        nVector += checkLocalCellPoint
        (
            mesh, positions, U(), vectorPatchVertices, vectorCellVertices
        );
    }
    // The positions inside the mesh (all of them, as the block's sides are
    // curved but the box is inside) are all exact for scalars
    EXPECT_GT(nScalar, 4*120);
    EXPECT_GT(nVector, nScalar/2);
    EXPECT_LT(nVector, nScalar);
    EXPECT_GT(patchVertices, 100);
    EXPECT_GT(cellVertices, 100);
    EXPECT_GT(vectorPatchVertices, 50);
}


namespace
{

//- The whole-field interpolation (interpolationCellPoint) at each probe in
//  its scale-free tetrahedron (probes' unset value where not found)
template<class Type>
tmp<Field<Type>> wholeFieldCellPoint
(
    const movingMeshProbes& probes,
    const GeometricField<Type, fvPatchField, volMesh>& vf
)
{
    const interpolationCellPoint<Type> whole(vf);
    tmp<Field<Type>> tvalues
    (
        new Field<Type>(probes.size(), Type(-VGREAT*pTraits<Type>::one))
    );
    forAll(probes, i)
    {
        const label celli = probes.elements()[i];
        if (celli != -1)
        {
            const scaleFreeCellPointWeight cpw(vf.mesh(), probes[i], celli);
            tvalues.ref()[i] = whole.interpolate(cpw.weights(), cpw.tet());
        }
    }
    return tvalues;
}

} // End anonymous namespace


TEST(movingMeshProbes, cellPointEqualsTheWholeFieldInterpolationToTheLastBit)
{
    // movingMeshProbes' cellPoint values (localCellPoint where exact, the
    // whole-field interpolation where not: the vectors on the wedge) equal
    // the whole-field interpolation's in the same (scale-free) tetrahedra
    // after every motion. (OpenFOAM's probes take other tetrahedra on this
    // micrometre mesh: scaleFreeCellPointWeight's tests below.)
    foamUnit::testCase tc("movingMeshProbes");
    autoPtr<fvMesh> meshPtr = tc.wedgeMesh();
    fvMesh& mesh = meshPtr();
    OStringStream os;
    os  << "fields (p U); interpolationScheme cellPoint; probeLocations (";
    const List<point> positions
    (
        randomPoints
        (
            point(2.01e-6, 0.01e-6, 0), point(17.99e-6, 7.99e-6, 0), 40, 9
        )
    );
    for (const point& x : positions)
    {
        os  << x << ' ';
    }
    os  << "(30e-6 1e-6 0));";   // outside the mesh: never found
    movingMeshProbes probes
    (
        "probes", tc.time(), dictionary(IStringStream(os.str())())
    );

    Random rnd(19);
    for (label n = 0; n < 4; ++n)
    {
        if (n)
        {
            ++tc.time();
            shakeWedge(mesh, rnd, 0.3e-6);
            probes.movePoints(mesh);
        }
        const tmp<volScalarField> p(smoothField<scalar>(mesh, "p"));
        const tmp<volVectorField> U(smoothField<vector>(mesh, "U"));
        const scalarField pLocal(probes.sampleCellPoint(p()));
        const scalarField pWhole(wholeFieldCellPoint(probes, p()));
        const vectorField ULocal(probes.sampleCellPoint(U()));
        const vectorField UWhole(wholeFieldCellPoint(probes, U()));
        forAll(probes, i)
        {
            EXPECT_TRUE(sameBits(pLocal[i], pWhole[i]))
                << "probe " << i << " after motion " << n << ": "
                << text(pLocal[i]) << " against " << text(pWhole[i]);
            EXPECT_TRUE(sameBits(ULocal[i], UWhole[i]))
                << "probe " << i << " after motion " << n << ": "
                << text(ULocal[i]) << " against " << text(UWhole[i]);
        }
        EXPECT_EQ(pLocal.last(), -VGREAT);
    }
}


namespace
{

//- The point a cellPointWeight (or scaleFreeCellPointWeight) samples: its
//  weights applied to its tetrahedron's vertices (the cell centre, the
//  face triangle's points)
template<class Weight>
point sampledPoint(const polyMesh& mesh, const Weight& cpw)
{
    const barycentric& w = cpw.weights();
    const triFace& tri = cpw.faceVertices();
    const pointField& pts = mesh.points();
    return
        w[0]*mesh.cellCentres()[cpw.cell()]
      + w[1]*pts[tri[0]] + w[2]*pts[tri[1]] + w[3]*pts[tri[2]];
}


//- For n random positions in the box x0 + s (x1 - x0) (those in the mesh):
//  the largest distance from the point scaleFreeCellPointWeight samples to
//  the position, relative to the cell's size (cube root of its volume);
//  the same for OpenFOAM's cellPointWeight in oldDistance; the number of
//  positions in the mesh
label samplingErrors
(
    const polyMesh& mesh,
    const point& x0,
    const point& x1,
    const label n,
    scalar& distance,
    scalar& oldDistance
)
{
    distance = 0;
    oldDistance = 0;
    label found = 0;
    for (const point& x : randomPoints(x0, x1, n, 23))
    {
        const label celli = mesh.findCell(x);
        if (celli == -1)
        {
            continue;
        }
        ++found;
        const scalar size = std::cbrt(mesh.cellVolumes()[celli]);
        const scaleFreeCellPointWeight cpw(mesh, x, celli);
        const barycentric& w = cpw.weights();
        for (direction k = 0; k < 4; ++k)
        {
            EXPECT_GT(w[k], -cellPointWeight::tol)
                << "at " << text(x) << " in cell " << celli;
        }
        distance = max(distance, mag(sampledPoint(mesh, cpw) - x)/size);
        const cellPointWeight old(mesh, x, celli);
        oldDistance =
            max(oldDistance, mag(sampledPoint(mesh, old) - x)/size);
    }
    return found;
}


//- 1 um cubes, 8 x 8 x 8 (walls)
autoPtr<fvMesh> micrometreCubes(foamUnit::testCase& tc)
{
    return tc.blockMesh
    (
        {8, 8, 8},
        [](const vector& s) { return 8e-6*s; },
        {"walls", "walls", "walls", "walls", "walls", "walls"},
        {"wall", "wall", "wall", "wall", "wall", "wall"}
    );
}

} // End anonymous namespace


TEST(scaleFreeCellPointWeight, samplesTheNominalPointInMicrometreMeshes)
{
    // The weights applied to the tetrahedron's vertices give the position
    // back to rounding (1e-10 of the cell's size: a field linear in space
    // with exact vertex values reads the exact value) in 1 um cubes, the
    // graded, sheared wedge and the curved, skewed block, before and after
    // a motion. OpenFOAM's cellPointWeight samples its first
    // tetrahedron's centroid there (|det| < SMALL = 1e-15): more than a
    // tenth of a cell away
    foamUnit::testCase tc("scaleFreeCellPointWeight");
    scalar distance, oldDistance;

    autoPtr<fvMesh> cubes = micrometreCubes(tc);
    EXPECT_EQ
    (
        samplingErrors
        (
            cubes(), point(1e-9, 1e-9, 1e-9),
            point(7.999e-6, 7.999e-6, 7.999e-6), 200, distance, oldDistance
        ),
        200
    );
    EXPECT_LT(distance, 1e-10);
    EXPECT_GT(oldDistance, 0.1);

    autoPtr<fvMesh> wedge = tc.wedgeMesh();
    EXPECT_EQ
    (
        samplingErrors
        (
            wedge(), point(2.01e-6, 0.01e-6, 0), point(17.99e-6, 7.99e-6, 0),
            100, distance, oldDistance
        ),
        100
    );
    EXPECT_LT(distance, 1e-10);
    EXPECT_GT(oldDistance, 0.1);

    autoPtr<fvMesh> skewedPtr = tc.blockMesh
    (
        {6, 5, 4},
        skewedBlock,
        {"walls", "walls", "walls", "walls", "walls", "walls"},
        {"wall", "wall", "wall", "wall", "wall", "wall"}
    );
    fvMesh& skewed = skewedPtr();
    const point x0(0.01e-6, 0.01e-6, 0.01e-6);
    const point x1(5.99e-6, 4.99e-6, 3.99e-6);
    EXPECT_GT
    (
        samplingErrors(skewed, x0, x1, 200, distance, oldDistance), 150
    );
    EXPECT_LT(distance, 1e-10);
    EXPECT_GT(oldDistance, 0.1);

    Random rnd(29);
    ++tc.time();
    shakeInterior(skewed, rnd, 0.15e-6);
    EXPECT_GT
    (
        samplingErrors(skewed, x0, x1, 200, distance, oldDistance), 150
    );
    EXPECT_LT(distance, 1e-10);
    EXPECT_GT(oldDistance, 0.1);
}


TEST(scaleFreeCellPointWeight, equalsCellPointWeightOnAMetreMesh)
{
    // Where OpenFOAM's test does not fire (metre-size cells) the tetrahedra
    // and weights are cellPointWeight's to the last bit; and the weights
    // do not depend on the length scale: the micrometre copy of the mesh
    // gives the same tetrahedra and weights to rounding
    foamUnit::testCase tc("scaleFreeCellPointWeight");
    const foamUnit::testCase::sideWords names
    {
        "walls", "walls", "walls", "walls", "walls", "walls"
    };
    const foamUnit::testCase::sideWords types
    {
        "wall", "wall", "wall", "wall", "wall", "wall"
    };
    autoPtr<fvMesh> metre = tc.blockMesh
    (
        {6, 5, 4},
        [](const vector& s) { return 1e6*skewedBlock(s); },
        names,
        types
    );
    autoPtr<fvMesh> micrometre =
        tc.blockMesh({6, 5, 4}, skewedBlock, names, types);

    label checked = 0;
    label inside = 0;
    for
    (
        const point& x
      : randomPoints
        (
            point(0.01, 0.01, 0.01), point(5.99, 4.99, 3.99), 200, 31
        )
    )
    {
        const label celli = metre->findCell(x);
        if (celli == -1)
        {
            continue;
        }
        ++checked;
        const scaleFreeCellPointWeight cpw(metre(), x, celli);
        const cellPointWeight old(metre(), x, celli);
        EXPECT_TRUE(sameBits(cpw.weights(), old.weights()))
            << "at " << text(x) << ": " << text(cpw.weights())
            << " against " << text(old.weights());
        EXPECT_EQ(cpw.faceVertices(), old.faceVertices());
        inside += (cmptMin(cpw.weights()) > 0);

        const point xMicro(1e-6*x);
        const label microCelli = micrometre->findCell(xMicro);
        ASSERT_EQ(microCelli, celli) << "at " << text(x);
        const scaleFreeCellPointWeight micro(micrometre(), xMicro, celli);
        EXPECT_EQ(micro.faceVertices(), cpw.faceVertices());
        for (direction k = 0; k < 4; ++k)
        {
            EXPECT_NEAR(micro.weights()[k], cpw.weights()[k], 1e-9)
                << "at " << text(x);
        }
    }
    EXPECT_GT(checked, 150);
    EXPECT_GT(inside, 100);   // strictly inside tetrahedra, not centroids
}


TEST(movingMeshProbes, cellPointIsExactForLinearFieldsInMicrometreCubes)
{
    // Inside 1 um cubes whose points are all interior the point values of
    // a field linear in space are exact (the eight cell centres around a
    // point are symmetric), so cellPoint reads the field's value at the
    // probe to rounding (relative 1e-10 of its spread); OpenFOAM's probes
    // read it at their first tetrahedron's centroid
    foamUnit::testCase tc("movingMeshProbes");
    autoPtr<fvMesh> meshPtr = micrometreCubes(tc);
    const fvMesh& mesh = meshPtr();
    const List<point> positions
    (
        randomPoints
        (
            point(1.001e-6, 1.001e-6, 1.001e-6),
            point(6.999e-6, 6.999e-6, 6.999e-6), 60, 37
        )
    );
    OStringStream os;
    os  << "fields (p); interpolationScheme cellPoint; probeLocations (";
    for (const point& x : positions)
    {
        os  << x << ' ';
    }
    os  << ");";
    const movingMeshProbes probes
    (
        "probes", tc.time(), dictionary(IStringStream(os.str())())
    );

    const auto f = [](const point& x)
    {
        return 1e5 + 3e11*x.x() - 7e11*x.y() + 2e11*x.z();
    };
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
    forAll(p.boundaryField(), patchi)
    {
        const vectorField& Cf = mesh.boundary()[patchi].Cf();
        scalarField values(Cf.size());
        forAll(Cf, facei)
        {
            values[facei] = f(Cf[facei]);
        }
        p.boundaryFieldRef()[patchi] == values;
    }
    const scalar spread = max(p.primitiveField()) - min(p.primitiveField());

    const scalarField values(probes.sampleCellPoint(p));
    const scalarField old(probes.sample(p));
    scalar error = 0;
    scalar oldError = 0;
    forAll(probes, i)
    {
        EXPECT_NE(probes.elements()[i], -1);
        error = max(error, mag(values[i] - f(probes[i]))/spread);
        oldError = max(oldError, mag(old[i] - f(probes[i]))/spread);
    }
    EXPECT_LT(error, 1e-10);
    EXPECT_GT(oldError, 1e-2);
}


// ************************************************************************* //
