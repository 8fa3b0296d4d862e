/*---------------------------------------------------------------------------*\
Description
    Unit tests of the FSI interface map (src/fsi/interfaceMap) and of
    globalInterfacePatch, between a fluid patch built with
    foamUnit::testCase::blockMesh and a solid mesh built in code
    (solid::Mesh::box, solid::Mesh::rectangle), for the maps and loads the
    tutorials use: the 3D projection map and the r-z faces map, each with
    both loads (mappedForces, pressure).

    - conservation: the solid nodal forces add up to the fluid force (3D),
      to the full-ring force in r-z (k_r = pi/sin(theta/2),
      k_z = 2 pi/sin(theta)), for non-matching faces and any face forces;
    - consistency: a rigid translation of the solid moves every fluid point
      by the same translation;
    - a uniform pressure gives the solid's consistent nodal forces
      f_a = p int N_a dA (r-z: 2 pi p int N_a r ds), computed here in
      closed form on the structured solid faces;
    - load pressure in r-z: the exact ring force of a uniform pressure for
      any face sizes, the exact nodal forces of a pressure linear in z;
    - the acoustic added damping of a uniform impedance Z (the Robin
      scheme's beta) adds up to Z times the (full-ring) area on the normal
      dofs.

    The interface dictionary is the Usage example of interfaceMap.H.

\*---------------------------------------------------------------------------*/

#include "interfaceMap.H"
#include "surfaceFields.H"
#include "globalInterfacePatch.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"
#include "foamTestCase.H"
#include "goldFile.H"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace Foam;
using constant::mathematical::pi;

namespace
{

const foamUnit::goldFile& gold()
{
    static const foamUnit::goldFile g("interfaceMap");
    return g;
}

//- The interface dictionary of interfaceMap.H's Usage
dictionary usageDict()
{
    IStringStream is
    (
        foamUnit::testCase::usageExample
        (
            "src/fsi/interfaceMap/interfaceMap.H"
        )
    );
    return dictionary(is).subDict("interface");
}

//- Size of the solid cube and of the fluid block beside it [m]
const scalar L = 1e-3;

//- 3D: the solid box [0, L]^3 (face set xmin is the interface), the fluid
//  block [-L, 0] x [0, L]^2 with its patch 'interface' at x = 0
struct case3D
{
    foamUnit::testCase tc;
    autoPtr<fvMesh> fluid;
    autoPtr<globalInterfacePatch> patch;
    solid::Mesh solid;

    case3D(const label nyF, const label nzF, const label nyS, const label nzS)
    :
        tc("interfaceMap3D"),
        solid(solid::Mesh::box(2, nyS, nzS, solid::Vec3(0, 0, 0),
            solid::Vec3(L, L, L)))
    {
        const word p("patch");
        fluid = tc.blockMesh
        (
            {2, nyF, nzF},
            [](const vector& s) { return L*vector(s.x() - 1, s.y(), s.z()); },
            {"far", "interface", "sides", "sides", "sides", "sides"},
            {p, p, p, p, p, p}
        );
        patch.reset
        (
            new globalInterfacePatch
            (
                fluid->boundaryMesh()[fluid->boundaryMesh().findPatchID
                ("interface")]
            )
        );
    }

    //- Solid nodes on y = 0 with their y dof prescribed (a symmetry plane)
    boolList fixedOnYmin() const
    {
        boolList fixed(3*solid.nNodes(), false);
        for (const int n : solid.nodeSet("ymin")) fixed[3*n + 1] = true;
        return fixed;
    }

    //- Area vectors of the fluid interface faces (outward of the fluid)
    vectorField Sf() const
    {
        const label patchi = fluid->boundaryMesh().findPatchID("interface");
        return fluid->Sf().boundaryField()[patchi];
    }
};

//- Sum of the nodal forces per component
vector sumForces(const scalarField& f, const label dim)
{
    vector s(Zero);
    forAll(f, i) s[i % dim] += f[i];
    return s;
}

//- Non-uniform face forces [N], smooth in the face centre
vectorField someForces(const vectorField& Sf, const pointField& Cf)
{
    vectorField F(Sf.size());
    forAll(F, i)
    {
        const point& c = Cf[i];
        F[i] =
            1e6*(1 + std::sin(3e3*c.y()) + 0.5*std::cos(2e3*c.z()))*Sf[i]
          + 1e5*mag(Sf[i])*vector(0.3, std::cos(4e3*c.y()), -0.2);
    }
    return F;
}

//- Consistent nodal forces of a uniform pressure p on the x = 0 face of
//  the solid box (ny x nz bilinear faces): p hy hz/4 per adjacent face,
//  along +x (the fluid pushes the solid)
scalarField consistentForces3D
(
    const interfaceMap& map,
    const solid::Mesh& solid,
    const label ny,
    const label nz,
    const scalar p
)
{
    const scalar hy = L/ny, hz = L/nz;
    scalarField f(map.nDofs(), Zero);
    forAll(map.nodes(), i)
    {
        const solid::Vec3& X = solid.X[map.nodes()[i]];
        const label j = std::lround(X[1]/hy), k = std::lround(X[2]/hz);
        const label nFaces =
            (j > 0 && j < ny ? 2 : 1)*(k > 0 && k < nz ? 2 : 1);
        f[3*i] = p*hy*hz/4*nFaces;
    }
    return f;
}

scalar maxRelDiff(const scalarField& a, const scalarField& b, const scalar s)
{
    return max(mag(a - b))/s;
}

} // End anonymous namespace


TEST(interfaceMap, globalInterfacePatchSerialIsThePatch)
{
    case3D c(3, 4, 5, 3);
    const polyPatch& pp =
        c.fluid->boundaryMesh()[c.fluid->boundaryMesh().findPatchID
        ("interface")];
    const globalInterfacePatch& g = c.patch();
    EXPECT_EQ(g.name(), "interface");
    EXPECT_EQ(g.size(), pp.size());
    EXPECT_EQ(g.localFaces(), pp.localFaces());
    EXPECT_EQ(g.localPoints(), pp.localPoints());
    EXPECT_EQ(g.faceCentres(), pointField(pp.faceCentres()));
    EXPECT_EQ(g.localToGlobal(), identity(pp.nPoints()));
    const vectorField Sf(pp.faceAreas());
    EXPECT_EQ(g.faceValues(Sf)(), Sf);
    EXPECT_EQ(g.localPointValues(pp.localPoints())(), pp.localPoints());
    // Several fields packed face by face: the same packing back (serial:
    // the rank's values; in parallel the ranks' in order, tests/blast
    // parallel.sh through the coupled step)
    scalarField packed(4*pp.size());
    forAll(pp, facei)
    {
        for (direction d = 0; d < 3; ++d) packed[4*facei + d] = Sf[facei][d];
        packed[4*facei + 3] = facei + 0.5;
    }
    EXPECT_EQ(g.packedFaceValues(packed, 4)(), packed);
}


TEST(interfaceMap, packedFaceValuesRefusesAWrongWidth)
{
    case3D c(3, 4, 5, 3);
    const globalInterfacePatch& g = c.patch();
    const scalarField packed(4*g.size() + 1, 1.0);
    EXPECT_THROW(g.packedFaceValues(packed, 4), Foam::error);
}


TEST(interfaceMap, projection3DConservesForce)
{
    // Non-matching: 3 x 4 fluid faces on 5 x 3 solid faces
    case3D c(3, 4, 5, 3);
    for (const bool symmetry : {false, true})
    {
        SCOPED_TRACE(symmetry ? "y prescribed on ymin" : "free");
        const interfaceMap map
        (
            c.patch(), c.solid, usageDict(),
            symmetry ? c.fixedOnYmin() : boolList()
        );
        ASSERT_EQ(map.mapType(), "projection");
        const vectorField F(someForces(c.Sf(), c.patch->faceCentres()));
        const vector fluidF(sum(F));
        const vector solidF(sumForces(map.nodalForces(F), 3));
        gold().check
        (
            "projection3D.relErrorRingForce",
            mag(map.ringForce(F) - fluidF)/mag(fluidF)
        );
        gold().check
        (
            "projection3D.relErrorTotalForce",
            mag(solidF - fluidF)/mag(fluidF)
        );
    }
}


TEST(interfaceMap, projection3DRigidTranslation)
{
    case3D c(3, 4, 5, 3);
    for (const bool symmetry : {false, true})
    {
        SCOPED_TRACE(symmetry ? "y prescribed on ymin" : "free");
        const interfaceMap map
        (
            c.patch(), c.solid, usageDict(),
            symmetry ? c.fixedOnYmin() : boolList()
        );
        // (a symmetry plane: no y translation)
        const vector t(2e-6, symmetry ? 0 : -1e-6, 3e-6);
        scalarField dofs(map.nDofs());
        forAll(dofs, i) dofs[i] = t[i % 3];
        const vectorField u(map.pointValues(dofs));
        ASSERT_EQ(u.size(), c.patch->localPoints().size());
        gold().check
        (
            "projection3D.relErrorTranslation", max(mag(u - t))/mag(t)
        );
    }
}


TEST(interfaceMap, pointValuesOfListedPointsAsOfAll)
{
    // The motion's points only (a rank's share, interfaceMotion::
    // usedPatchPoints): each listed point has the bits of the whole
    // patch's values, the others are zero; with pinned components too
    case3D c(3, 4, 5, 3);
    for (const bool symmetry : {false, true})
    {
        SCOPED_TRACE(symmetry ? "y prescribed on ymin" : "free");
        const interfaceMap map
        (
            c.patch(), c.solid, usageDict(),
            symmetry ? c.fixedOnYmin() : boolList()
        );
        scalarField dofs(map.nDofs());
        forAll(dofs, i) dofs[i] = 1e-6*std::sin(0.7*i + 0.3);
        const vectorField all(map.pointValues(dofs));
        labelList listed;
        for (label p = 1; p < all.size(); p += 3) listed.append(p);
        const vectorField some(map.pointValues(dofs, listed));
        ASSERT_EQ(some.size(), all.size());
        label nonZero = 0;
        forAll(all, p)
        {
            const bool isListed = p % 3 == 1;
            for (direction d = 0; d < 3; ++d)
            {
                EXPECT_EQ(some[p][d], isListed ? all[p][d] : 0.0) << p;
            }
            nonZero += isListed && mag(all[p]) > 0;
        }
        EXPECT_GT(nonZero, 0);
    }
}


TEST(interfaceMap, projection3DUniformPressureGivesConsistentForces)
{
    // Both loads the tutorials may use: the projection map's forces and
    // load pressure (the fluid pressure on the solid's own faces), for
    // matching and non-matching faces. The projection map's nodal forces
    // are p sum_q A_q N_a(x_q) over its quadrature of the fluid faces:
    // consistent for matching faces (to the 2^-32 rounding of the map's
    // weights), for non-matching faces up to that quadrature's error (a
    // gold value: about 1 % at 2 x 2 subtriangles per fluid triangle)
    const scalar p = 5e7;
    // Fluid faces ny x nz, solid faces ny x nz
    const List<FixedList<label, 4>> sizes({{4, 3, 4, 3}, {3, 4, 5, 3}});
    for (const FixedList<label, 4>& n : sizes)
    {
        SCOPED_TRACE
        (
            "fluid " + std::to_string(n[0]) + " x " + std::to_string(n[1])
          + ", solid " + std::to_string(n[2]) + " x " + std::to_string(n[3])
        );
        case3D c(n[0], n[1], n[2], n[3]);
        dictionary dict(usageDict());
        dict.set("load", word("pressure"));
        const interfaceMap map(c.patch(), c.solid, dict);
        ASSERT_TRUE(map.pressureLoad());
        const scalarField exact
        (
            consistentForces3D(map, c.solid, n[2], n[3], p)
        );
        const scalar scale = p*L*L/(n[2]*n[3]);
        const vectorField F(p*c.Sf());
        const bool matching = n[0] == n[2] && n[1] == n[3];
        gold().check
        (
            matching
          ? "projection3D.uniformPressure.relError"
          : "projection3D.nonMatchingUniformPressure.relError",
            maxRelDiff(map.nodalForces(F), exact, scale)
        );
        gold().check
        (
            "pressureLoad3D.uniformPressure.relError",
            maxRelDiff
            (
                map.nodalPressureForces
                (
                    F, c.Sf(), scalarField(map.nDofs(), Zero)
                ),
                exact, scale
            )
        );
        // The fluid's acoustic added damping (Robin): a uniform impedance
        // Z on faces normal to x gives Z |Sf| on the x dofs, in total Z
        // times the area, nothing on the tangential dofs
        const scalar Z = 1.5e6;
        const scalarField D
        (
            map.nodalImpedance(scalarField(c.Sf().size(), Z), c.Sf())
        );
        gold().check
        (
            "projection3D.impedance.relErrorTotal",
            mag(sumForces(D, 3) - vector(Z*L*L, 0, 0))/(Z*L*L)
        );

        // A rigid translation of the solid leaves the pressure load as is
        scalarField u(map.nDofs());
        forAll(u, i) u[i] = vector(1e-6, -2e-6, 5e-7)[i % 3];
        gold().check
        (
            "pressureLoad3D.translated.relError",
            maxRelDiff(map.nodalPressureForces(F, c.Sf(), u), exact, scale)
        );
    }
}


TEST(interfaceMap, pressureQuadratureConvergesToTheOverlapAverage)
{
    // load pressure in 3D with fluid faces coarser than the solid's (the
    // quarter's pole cap: 1-1.6 um water faces on 0.3-1 um membrane
    // faces): each solid face takes the area average of the fluid
    // pressure at the quadrature points that fall on it, a face with none
    // its nearest face's. Exact: the overlap average of the fluid's
    // piecewise-constant pressure over each solid face. With the
    // triangles' centroids alone (pressureQuadrature 1) most of the 5 x 5
    // solid faces under the 2 x 2 fluid faces are sampled off or not at
    // all; nSub^2 subtriangles per triangle converge to the overlap
    // average (first order in 1/nSub: the subtriangles straddling a solid
    // face's edge)
    const label nyF = 3, nzF = 2, nyS = 7, nzS = 5;
    case3D c(nyF, nzF, nyS, nzS);
    const scalar p0 = 5e7;
    // Fluid face pressures: distinct, p0 (1 + j + 2 k)/4 for face (j, k)
    const label patchi = c.fluid->boundaryMesh().findPatchID("interface");
    const vectorField Cf(c.fluid->Cf().boundaryField()[patchi]);
    const vectorField Sf(c.Sf());
    scalarField pF(Sf.size());
    forAll(pF, f)
    {
        const label j = std::floor(Cf[f].y()/(L/nyF));
        const label k = std::floor(Cf[f].z()/(L/nzF));
        pF[f] = p0*(1 + j + 2*k)/4;
    }
    // Exact nodal forces: each solid face's overlap average, p hy hz/4 on
    // its four nodes along +x
    const scalar hy = L/nyS, hz = L/nzS;
    const auto overlap = [](scalar a0, scalar a1, scalar b0, scalar b1)
    {
        return max(scalar(0), min(a1, b1) - max(a0, b0));
    };
    const auto exactForces = [&](const interfaceMap& map)
    {
        scalarField f(map.nDofs(), Zero);
        forAll(map.nodes(), i)
        {
            const solid::Vec3& X = c.solid.X[map.nodes()[i]];
            const label jn = std::lround(X[1]/hy), kn = std::lround(X[2]/hz);
            for (label js = jn - 1; js <= jn; ++js)
            for (label ks = kn - 1; ks <= kn; ++ks)
            {
                if (js < 0 || js >= nyS || ks < 0 || ks >= nzS) continue;
                scalar P = 0;
                forAll(pF, ff)
                {
                    const scalar y0 = L/nyF*std::floor(Cf[ff].y()/(L/nyF));
                    const scalar z0 = L/nzF*std::floor(Cf[ff].z()/(L/nzF));
                    P += pF[ff]
                       *overlap(js*hy, (js + 1)*hy, y0, y0 + L/nyF)
                       *overlap(ks*hz, (ks + 1)*hz, z0, z0 + L/nzF);
                }
                f[3*i] += P/4;
            }
        }
        return f;
    };
    const scalar scale = p0*hy*hz;
    scalarField err(12);
    forAll(err, n)
    {
        dictionary dict(usageDict());
        dict.set("load", word("pressure"));
        dict.set("pressureQuadrature", label(n + 1));
        const interfaceMap map(c.patch(), c.solid, dict);
        err[n] = maxRelDiff
        (
            map.nodalPressureForces
            (
                vectorField(pF*Sf), Sf, scalarField(map.nDofs(), Zero)
            ),
            exactForces(map),
            scale
        );
    }
    // Reference values (some nSub fall exactly on the solid faces' edges
    // for these commensurate grids: the error is not monotonic)
    gold().check("pressureLoad3D.overlapAverage.nSub1.relError", err[0]);
    gold().check("pressureLoad3D.overlapAverage.nSub12.relError", err[11]);
    // Convergence (first order, not monotonic): from nSub 8 on, below a
    // fifth of the centroids' error
    EXPECT_GT(err[0], 0.03);
    for (label n = 7; n < 12; ++n)
    {
        EXPECT_LT(err[n], 0.2*err[0]) << "nSub " << n + 1;
    }
}


namespace
{

//- r-z: the solid rectangle [r0, r1] x [0, H] and a fluid wedge of angle
//  theta (axis y, points at azimuth +-theta/2) on its side r = r1
//  (radial) or on its top z = H (axial)
struct caseRz
{
    foamUnit::testCase tc;
    autoPtr<fvMesh> fluid;
    autoPtr<globalInterfacePatch> patch;
    solid::Mesh solid;
    scalar theta;

    static constexpr scalar r0 = 0.5e-3, r1 = 1e-3, H = 1e-3;

    caseRz(const bool radial, const label nF, const label nS)
    :
        tc("interfaceMapRz"),
        solid
        (
            radial
          ? solid::Mesh::rectangle(2, nS, r0, r1, 0, H)
          : solid::Mesh::rectangle(nS, 2, r0, r1, 0, H)
        ),
        theta(5*pi/180)
    {
        const word p("patch");
        const scalar th = theta;
        auto wedge = [th](const scalar r, const scalar z, const scalar s)
        {
            const scalar phi = th*(s - 0.5);
            return point(r*std::cos(phi), z, r*std::sin(phi));
        };
        if (radial)
        {
            fluid = tc.blockMesh
            (
                {2, nF, 1},
                [&](const vector& s)
                {
                    return wedge(r1 + 0.5e-3*s.x(), H*s.y(), s.z());
                },
                {"interface", "far", "bottom", "top", "front", "back"},
                {p, p, p, p, p, p}
            );
        }
        else
        {
            fluid = tc.blockMesh
            (
                {nF, 2, 1},
                [&](const vector& s)
                {
                    return wedge(r0 + (r1 - r0)*s.x(), H + 0.5e-3*s.y(), s.z());
                },
                {"inner", "outer", "interface", "far", "front", "back"},
                {p, p, p, p, p, p}
            );
        }
        patch.reset
        (
            new globalInterfacePatch
            (
                fluid->boundaryMesh()[fluid->boundaryMesh().findPatchID
                ("interface")]
            )
        );
    }

    vectorField Sf() const
    {
        const label patchi = fluid->boundaryMesh().findPatchID("interface");
        return fluid->Sf().boundaryField()[patchi];
    }

    //- The Usage dictionary with the r-z entries: the solid face set, the
    //  default map (faces; the example's projection is 3D only)
    dictionary dict(const bool radial) const
    {
        dictionary d(usageDict());
        d.set("solidFaceSet", word(radial ? "right" : "top"));
        d.remove("map");
        return d;
    }
};

} // End anonymous namespace


TEST(interfaceMap, rzFacesFullRingForces)
{
    const scalar p = 5e7;
    for (const bool radial : {true, false})
    {
        // Fluid faces, solid faces along the interface
        const List<FixedList<label, 2>> sizes({{4, 4}, {3, 5}});
        for (const FixedList<label, 2>& n : sizes)
        {
            SCOPED_TRACE
            (
                std::string(radial ? "radial" : "axial")
              + " fluid " + std::to_string(n[0])
              + " solid " + std::to_string(n[1])
            );
            caseRz c(radial, n[0], n[1]);
            const interfaceMap map(c.patch(), c.solid, c.dict(radial));
            ASSERT_TRUE(map.axisymmetric());
            ASSERT_EQ(map.mapType(), "faces");
            EXPECT_NEAR(map.ringFactorRadial(), pi/std::sin(c.theta/2), 1e-9);
            EXPECT_NEAR(map.ringFactorAxial(), 2*pi/std::sin(c.theta), 1e-9);

            // Uniform pressure: the exact full-ring force of the surface,
            // pushing the solid (-r on its side, -z on its top)
            const vectorField F(p*c.Sf());
            const vector ring(map.ringForce(F));
            const vector exact = radial
                ? vector(-p*2*pi*c.r1*c.H, 0, 0)
                : vector(0, -p*pi*(sqr(c.r1) - sqr(c.r0)), 0);
            gold().check("rz.ringForce.relError", mag(ring - exact)/mag(exact));

            // Conservation for any face forces
            const vectorField G(someForces(c.Sf(), c.patch->faceCentres()));
            const vector ringG(map.ringForce(G));
            gold().check
            (
                "rz.totalForce.relError",
                mag(sumForces(map.nodalForces(G), 2) - ringG)/mag(ringG)
            );

            // Matching faces: the consistent nodal forces of the ring,
            // 2 pi p int N_a r ds over each solid segment
            if (n[0] == n[1])
            {
                scalarField exactF(map.nDofs(), Zero);
                for
                (
                    const auto& seg :
                    c.solid.faceSets.at(radial ? "right" : "top")
                )
                {
                    const solid::Vec3& a = c.solid.X[seg[0]];
                    const solid::Vec3& b = c.solid.X[seg[1]];
                    const scalar len = (b - a).norm();
                    const scalar fa = 2*pi*p*len*(2*a[0] + b[0])/6;
                    const scalar fb = 2*pi*p*len*(a[0] + 2*b[0])/6;
                    const label d = radial ? 0 : 1;
                    forAll(map.nodes(), i)
                    {
                        if (map.nodes()[i] == seg[0]) exactF[2*i + d] -= fa;
                        if (map.nodes()[i] == seg[1]) exactF[2*i + d] -= fb;
                    }
                }
                gold().check
                (
                    "rz.matchingUniformPressure.relError",
                    max(mag(map.nodalForces(F) - exactF))/max(mag(exactF))
                );
            }

            // Acoustic added damping of a uniform impedance Z: Z times the
            // full-ring area on the normal dofs, nothing on the others
            const scalar Z = 1.5e6;
            const scalarField D
            (
                map.nodalImpedance(scalarField(c.Sf().size(), Z), c.Sf())
            );
            const scalar ringArea = radial
                ? 2*pi*c.r1*c.H : pi*(sqr(c.r1) - sqr(c.r0));
            const vector exactD = radial
                ? vector(Z*ringArea, 0, 0) : vector(0, Z*ringArea, 0);
            gold().check
            (
                "rz.impedance.relErrorTotal",
                mag(sumForces(D, 2) - exactD)/(Z*ringArea)
            );

            // An axial translation of the solid moves every fluid point
            const scalar t = 3e-6;
            scalarField dofs(map.nDofs(), Zero);
            forAll(map.nodes(), i) dofs[2*i + 1] = t;
            const vectorField u(map.pointValues(dofs));
            gold().check
            (
                "rz.relErrorTranslation",
                max(mag(u - vector(0, t, 0)))/t
            );
        }
    }
}


TEST(interfaceMap, rzUnseenModesAreCounted)
{
    // The fluid patch points see the solid interface at their projections
    // only: n_F + 1 point positions along the interface (the wedge's two
    // azimuths repeat them) against n_S + 1 solid nodes, all free. A solid
    // finer than the fluid leaves n_S - n_F patterns unseen; matching or
    // finer fluid faces see all (cellBlastFoam refuses the first,
    // tests/blast/unseenModes.sh)
    for (const bool radial : {true, false})
    {
        for
        (
            const FixedList<label, 3>& n :
            List<FixedList<label, 3>>({{4, 4, 0}, {3, 5, 2}, {5, 3, 0},
                                       {2, 7, 5}})
        )
        {
            SCOPED_TRACE
            (
                std::string(radial ? "radial" : "axial")
              + " fluid " + std::to_string(n[0])
              + " solid " + std::to_string(n[1])
            );
            caseRz c(radial, n[0], n[1]);
            const interfaceMap map(c.patch(), c.solid, c.dict(radial));
            scalar sigmaRatio = -1;
            EXPECT_EQ(map.unseenModes(boolList(), sigmaRatio), n[2]);
            if (n[2] == 0)
            {
                EXPECT_GT(sigmaRatio, 0.1);
            }
            else
            {
                EXPECT_LT(sigmaRatio, 1e-6);
            }
        }
    }
}


TEST(interfaceMap, rzPressureLoadRingForces)
{
    // load pressure in r-z: the fluid pressure averaged over each solid
    // segment, integrated by solid::PressureLoad per full ring. A uniform
    // pressure gives the exact ring force of the solid's surface for any
    // face sizes (fluid 1 face on 6 solid faces: solid faces without a
    // quadrature point take their donor's pressure); a pressure linear in
    // z on the side r = r1 with matching faces the exact nodal forces
    // 2 pi r1 P_s len/2 (P_s the segment's mean); a rigid translation of
    // the solid changes nothing
    const scalar p = 5e7;
    for (const bool radial : {true, false})
    {
        const List<FixedList<label, 2>> sizes({{4, 4}, {3, 5}, {1, 6}});
        for (const FixedList<label, 2>& n : sizes)
        {
            SCOPED_TRACE
            (
                std::string(radial ? "radial" : "axial")
              + " fluid " + std::to_string(n[0])
              + " solid " + std::to_string(n[1])
            );
            caseRz c(radial, n[0], n[1]);
            dictionary dict(c.dict(radial));
            dict.set("load", word("pressure"));
            const interfaceMap map(c.patch(), c.solid, dict);
            ASSERT_TRUE(map.pressureLoad());
            const scalarField u0(map.nDofs(), Zero);

            const vectorField F(p*c.Sf());
            const scalarField f(map.nodalPressureForces(F, c.Sf(), u0));
            const vector exact = radial
                ? vector(-p*2*pi*c.r1*c.H, 0, 0)
                : vector(0, -p*pi*(sqr(c.r1) - sqr(c.r0)), 0);
            gold().check
            (
                "rz.pressureLoad.uniformTotal.relError",
                mag(sumForces(f, 2) - exact)/mag(exact)
            );

            scalarField u(map.nDofs());
            forAll(u, i) u[i] = (i % 2 ? 3e-6 : 0);
            gold().check
            (
                "rz.pressureLoad.translated.relError",
                max(mag(map.nodalPressureForces(F, c.Sf(), u) - f))
               /max(mag(f))
            );

            if (!radial || n[0] != n[1])
            {
                continue;
            }
            // p0 + g z on the side, from 50 to 150 MPa over the height
            const scalar g = 1e8/c.H;
            const pointField Cf(c.patch->faceCentres());
            vectorField G(F.size());
            forAll(G, i) G[i] = (p + g*Cf[i].y())*c.Sf()[i];
            scalarField exactF(map.nDofs(), Zero);
            for (const auto& seg : c.solid.faceSets.at("right"))
            {
                const solid::Vec3& a = c.solid.X[seg[0]];
                const solid::Vec3& b = c.solid.X[seg[1]];
                const scalar Ps = p + g*0.5*(a[1] + b[1]);
                const scalar fa = 2*pi*c.r1*Ps*(b - a).norm()/2;
                forAll(map.nodes(), i)
                {
                    if (map.nodes()[i] == seg[0] || map.nodes()[i] == seg[1])
                    {
                        exactF[2*i] -= fa;
                    }
                }
            }
            gold().check
            (
                "rz.pressureLoad.linearZ.relError",
                max(mag(map.nodalPressureForces(G, c.Sf(), u0) - exactF))
               /max(mag(exactF))
            );
        }
    }
}


TEST(interfaceMap, rzRefusesPressureQuadrature)
{
    // The r-z force quadrature is two segments of two Gauss points per
    // face: pressureQuadrature (3D) other than 1 is refused there
    caseRz c(true, 3, 5);
    dictionary dict(c.dict(true));
    dict.name() = "constant/fsiProperties/interface";
    dict.set("load", word("pressure"));
    dict.set("pressureQuadrature", label(1));
    EXPECT_NO_THROW(interfaceMap(c.patch(), c.solid, dict));
    dict.set("pressureQuadrature", label(4));
    try
    {
        interfaceMap map(c.patch(), c.solid, dict);
        ADD_FAILURE() << "accepted";
    }
    catch (const Foam::IOerror& err)
    {
        EXPECT_EQ(err.ioFileName(), "constant/fsiProperties/interface");
        EXPECT_NE
        (
            err.message().find("pressureQuadrature 4 is for 3D"),
            std::string::npos
        ) << err.message();
    }
}


TEST(interfaceMap, badDictionariesNameTheEntry)
{
    case3D c(3, 4, 5, 3);
    struct badCase
    {
        word key;
        std::string value;
        std::vector<std::string> message;
    };
    for
    (
        const badCase& b :
        {
            badCase{"solidFaceSet", "nowhere", {"nowhere", "xmin", "zmax"}},
            badCase
            {
                "mapTolerance", "-0.1",
                {"entry 'mapTolerance' = -0.1", "(0, inf)"}
            },
            badCase{"map", "nearest", {"map nearest is not valid"}},
            // the valid words named (readOneOf, fix19f)
            badCase
            {
                "load", "traction",
                {"entry 'load'", "= 'traction' is not one of the valid "
                 "values (mappedForces pressure)"}
            },
            badCase
            {
                "load", "projection",
                {"load projection is now 'load mappedForces'", "pressure"}
            },
            badCase
            {
                "pressureQuadrature", "0",
                {"entry 'pressureQuadrature' = 0", "[1, 16]"}
            },
            badCase
            {
                "pressureQuadrature", "17",
                {"entry 'pressureQuadrature' = 17", "[1, 16]"}
            }
        }
    )
    {
        SCOPED_TRACE(b.key);
        dictionary dict(usageDict());
        dict.name() = "constant/fsiProperties/interface";
        dict.remove(b.key);
        IStringStream is(b.key + " " + b.value + ";");
        dict.merge(dictionary(is));
        try
        {
            interfaceMap map(c.patch(), c.solid, dict);
            ADD_FAILURE() << "accepted";
        }
        catch (const Foam::IOerror& err)
        {
            EXPECT_EQ(err.ioFileName(), "constant/fsiProperties/interface");
            for (const std::string& m : b.message)
            {
                EXPECT_NE(err.message().find(m), std::string::npos)
                    << "no '" << m << "' in: " << err.message();
            }
        }
    }

    // A solid that does not touch the fluid patch: the gap is named
    solid::Mesh far(solid::Mesh::box(2, 3, 3, solid::Vec3(L, 0, 0),
        solid::Vec3(2*L, L, L)));
    try
    {
        interfaceMap map(c.patch(), far, usageDict());
        ADD_FAILURE() << "a solid 1 mm off the fluid patch was accepted";
    }
    catch (const Foam::error& err)
    {
        EXPECT_NE(err.message().find("lie off the solid interface"),
            std::string::npos) << err.message();
    }
}
