/*---------------------------------------------------------------------------*\
Description
    Unit tests of MUSCLReconstruction (src/riemannFluxes): the face states
    of its single face loop against OpenFOAM's own limited schemes, on a
    small non-uniform, non-orthogonal wedge mesh with a patch, a wall, a
    symmetry plane and the two wedge sides:

    - every limiter it accepts (MUSCL, vanLeer, Minmod, vanAlbada, upwind;
      the V schemes for U): owner-side and neighbour-side states equal
      fvc::interpolate(phi, +-1, "reconstruct(phi)") to the last bit, on
      a field with smooth parts, plateaus and a jump;
    - TVD bounds on a uniform row of cells: each face state lies between
      the two cell values, and at a local extremum the state is the
      upwind cell's (first order);
    - the multidimensional limiters (BarthJespersen, venkatakrishnan; U
      per component): a linear field reconstructed exactly at the face
      centres of a sheared (non-orthogonal, affine) mesh; on a skewed,
      non-affine mesh with a step across it every face state within the
      min/max of its cell and the cell's face neighbours, where the
      unlimited face-centre extrapolation is not;
    - U in the face's frame (normalTangential N T): a linear field
      reconstructed exactly at the face centres of a graded mesh (MUSCL
      for both parts), its normal component so with an upwind tangential
      part that is the upwind cell's; on a rotated row of cells with an
      oblique velocity step the normal component bounded by the two
      cells' and first order at its extrema, a purely normal velocity
      reconstructed as by MUSCLV; a malformed entry refused;
    - the least-squares cell gradients (gradSchemes leastSquares,
      pointCellsLeastSquares): a linear field's gradient exact on a
      skewed, non-affine mesh (leastSquares in the cells without a
      boundary face) where Gauss linear's is not;
    - the characteristic reconstruction (characteristic N T): a linear
      field's states those of the primitive MUSCL on a sheared mesh; on a
      1D Riemann problem's data (a step in the wave along n and in the
      tangential velocity), along x and on a row turned to the normal, the
      wave against n second order across the step where the primitive
      limiter cuts it, the jumping waves bounded by their cells' values;
      mismatched schemes and a missing sound speed refused;
    - a scheme it does not reproduce (a scalar limiter for U, a central
      scheme, a limiter with a coefficient, a gradient scheme other than
      Gauss linear and the least-squares ones) stops with an error naming system/fvSchemes, the entry
      and the valid names.

\*---------------------------------------------------------------------------*/

#include "MUSCLReconstruction.H"
#include "fvc.H"
#include "zeroGradientFvPatchFields.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "foamTestCase.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <regex>
#include <string>

using namespace Foam;

namespace
{

const char* header =
    "FoamFile { version 2.0; format ascii; class dictionary;"
    " object fvSchemes; }\n"
    "ddtSchemes { default Euler; }\n"
    "divSchemes { default none; }\n"
    "laplacianSchemes { default Gauss linear corrected; }\n"
    "snGradSchemes { default corrected; }\n";

//- system/fvSchemes: the Usage example of MUSCLReconstruction.H with the
//  given schemes of rho and p (scalar), U (vector), and gradient
void writeSchemes
(
    const foamUnit::testCase& tc,
    const std::string& scalarScheme,
    const std::string& vectorScheme,
    const std::string& gradScheme = "Gauss linear",
    const std::string& pScheme = ""
)
{
    std::string schemes
    (
        foamUnit::testCase::usageExample
        (
            "src/riemannFluxes/MUSCLReconstruction/MUSCLReconstruction.H"
        )
    );
    const std::pair<std::string, std::string> entries[] =
    {
        {"reconstruct\\(rho\\) +MUSCL;", "reconstruct(rho) " + scalarScheme},
        {"reconstruct\\(U\\) +MUSCLV;", "reconstruct(U) " + vectorScheme},
        {
            "reconstruct\\(p\\) +MUSCL;",
            "reconstruct(p) " + (pScheme.empty() ? scalarScheme : pScheme)
        }
    };
    for (const auto& e : entries)
    {
        const std::regex entry(e.first);
        EXPECT_TRUE(std::regex_search(schemes, entry))
            << "no " << e.first << " in the Usage of MUSCLReconstruction.H";
        schemes = std::regex_replace(schemes, entry, e.second + ';');
    }

    OStringStream os;
    os  << header << "gradSchemes { default " << gradScheme.c_str() << "; }\n"
        << schemes.c_str();
    tc.writeFile("system/fvSchemes", os.str());
}


//- rho [kg/m^3], U [m/s], p [Pa]: smooth parts, plateaus (equal
//  neighbours: the limiters' clamped branch) and a jump
struct primitiveFields
{
    volScalarField rho;
    volVectorField U;
    volScalarField p;

    static IOobject io(const fvMesh& mesh, const word& name)
    {
        return IOobject(name, mesh.time().timeName(), mesh);
    }

    explicit primitiveFields(const fvMesh& mesh)
    :
        rho
        (
            io(mesh, "rho"), mesh, dimensionedScalar(dimDensity, Zero),
            zeroGradientFvPatchScalarField::typeName
        ),
        U
        (
            io(mesh, "U"), mesh, dimensionedVector(dimVelocity, Zero),
            zeroGradientFvPatchVectorField::typeName
        ),
        p
        (
            io(mesh, "p"), mesh, dimensionedScalar(dimPressure, Zero),
            zeroGradientFvPatchScalarField::typeName
        )
    {
        const vectorField& C = mesh.C();
        forAll(C, celli)
        {
            const scalar x = C[celli].x()/1e-6;
            const scalar y = C[celli].y()/1e-6;
            const scalar wave = std::sin(0.9*x)*std::cos(0.7*y);
            const scalar jump = x > 9 ? 1 : 0;
            rho[celli] = 1000 + max(30*wave, 5) + 80*jump;
            U[celli] = vector(20*wave - 40*jump, min(15*std::cos(x*y), 4), 0);
            p[celli] = 1e5 + 3e7*jump + max(2e6*std::sin(1.3*y + x), -1e6);
        }
        rho.correctBoundaryConditions();
        U.correctBoundaryConditions();
        p.correctBoundaryConditions();
    }
};


//- Number of internal faces where a and b differ in any bit
template<class Type>
label nDiffering(const Field<Type>& a, const Field<Type>& b)
{
    label n = 0;
    forAll(a, facei)
    {
        if (std::memcmp(&a[facei], &b[facei], sizeof(Type)) != 0)
        {
            ++n;
        }
    }
    return n;
}


//- Owner side (faceFlux +1) and neighbour side (-1) by OpenFOAM's own
//  limited scheme, as the solver computed them before MUSCLReconstruction
template<class Type>
void expectOpenFOAMStates
(
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    const Field<Type>& left,
    const Field<Type>& right,
    const word& what
)
{
    const fvMesh& mesh = vf.mesh();
    const word scheme("reconstruct(" + vf.name() + ')');
    const surfaceScalarField pos
    (
        primitiveFields::io(mesh, "pos"),
        mesh,
        dimensionedScalar("one", dimless, 1)
    );
    const surfaceScalarField neg
    (
        primitiveFields::io(mesh, "neg"),
        mesh,
        dimensionedScalar("minusOne", dimless, -1)
    );
    const Field<Type> refL
    (
        fvc::interpolate(vf, pos, scheme)().primitiveField()
    );
    const Field<Type> refR
    (
        fvc::interpolate(vf, neg, scheme)().primitiveField()
    );
    ASSERT_EQ(left.size(), mesh.nInternalFaces());
    EXPECT_EQ(nDiffering(left, refL), 0)
        << what << ": owner-side " << vf.name() << " of "
        << left.size() << " faces";
    EXPECT_EQ(nDiffering(right, refR), 0)
        << what << ": neighbour-side " << vf.name() << " of "
        << right.size() << " faces";
}


//- The error message of a MUSCLReconstruction on the given schemes
std::string refusal
(
    const std::string& scalarScheme,
    const std::string& vectorScheme,
    const std::string& gradScheme = "Gauss linear"
)
{
    foamUnit::testCase tc("MUSCLReconstruction");
    writeSchemes(tc, scalarScheme, vectorScheme, gradScheme);
    autoPtr<fvMesh> mesh = tc.wedgeMesh();
    try
    {
        MUSCLReconstruction r(mesh());
        ADD_FAILURE() << "accepted " << scalarScheme << ", " << vectorScheme
            << ", grad " << gradScheme;
    }
    catch (const Foam::IOerror& err)
    {
        return err.message();
    }
    return "";
}

} // End anonymous namespace


TEST(MUSCLReconstruction, faceStatesEqualOpenFOAMsLimitedSchemesBitwise)
{
    const FixedList<Pair<word>, 5> schemes
    ({
        {"MUSCL", "MUSCLV"},
        {"vanLeer", "vanLeerV"},
        {"Minmod", "MinmodV"},
        {"vanAlbada", "vanAlbadaV"},
        {"upwind", "upwind"}
    });
    for (const Pair<word>& s : schemes)
    {
        foamUnit::testCase tc("MUSCLReconstruction");
        writeSchemes(tc, s.first(), s.second());
        autoPtr<fvMesh> mesh = tc.wedgeMesh();
        const primitiveFields f(mesh());

        MUSCLReconstruction r(mesh());
        MUSCLReconstruction::states L, R;
        r.reconstruct(f.rho, f.U, f.p, L, R);

        const word what(s.first() + '/' + s.second());
        expectOpenFOAMStates(f.rho, L.rho, R.rho, what);
        expectOpenFOAMStates(f.U, L.U, R.U, what);
        expectOpenFOAMStates(f.p, L.p, R.p, what);

        // Not trivially equal: the limited states differ from upwind
        if (s.first() != "upwind")
        {
            label nLimited = 0;
            forAll(L.rho, facei)
            {
                nLimited +=
                    L.rho[facei] != f.rho[mesh().owner()[facei]] ? 1 : 0;
            }
            EXPECT_GT(nLimited, 10) << what;
        }
    }
}


TEST(MUSCLReconstruction, faceStatesOfMixedLimitersEqualOpenFOAMsBitwise)
{
    // rho, U and p with different limiters take the general face loop
    // (the default, one limiter for all three, its own: the test above);
    // both are OpenFOAM's limited schemes bit for bit
    const FixedList<FixedList<word, 3>, 3> schemes
    ({
        {"vanLeer", "MUSCLV", "Minmod"},
        {"MUSCL", "vanAlbadaV", "MUSCL"},
        {"MUSCL", "upwind", "MUSCL"}
    });
    for (const FixedList<word, 3>& s : schemes)
    {
        foamUnit::testCase tc("MUSCLReconstruction");
        writeSchemes(tc, s[0], s[1], "Gauss linear", s[2]);
        autoPtr<fvMesh> mesh = tc.wedgeMesh();
        const primitiveFields f(mesh());

        MUSCLReconstruction r(mesh());
        ASSERT_EQ(r.pLimiter(), MUSCLReconstruction::scalarNames[s[2]]);
        MUSCLReconstruction::states L, R;
        r.reconstruct(f.rho, f.U, f.p, L, R);

        const word what(s[0] + '/' + s[1] + '/' + s[2]);
        expectOpenFOAMStates(f.rho, L.rho, R.rho, what);
        expectOpenFOAMStates(f.U, L.U, R.U, what);
        expectOpenFOAMStates(f.p, L.p, R.p, what);
    }
}


TEST(MUSCLReconstruction, cellGradientsEqualOpenFOAMsGaussLinearBitwise)
{
    // The Gauss-linear cell gradients, of the three fields in one face
    // loop (every field limited: the default) or each in its own (U
    // upwind), against fvc::grad on the wedge mesh (its wedge patches'
    // values in the sums), every cell bit for bit
    const FixedList<Pair<word>, 2> schemes
    ({
        {"MUSCL", "MUSCLV"},
        {"MUSCL", "upwind"}
    });
    for (const Pair<word>& s : schemes)
    {
        foamUnit::testCase tc("MUSCLReconstruction");
        writeSchemes(tc, s.first(), s.second());
        autoPtr<fvMesh> mesh = tc.wedgeMesh();
        const primitiveFields f(mesh());

        MUSCLReconstruction r(mesh());
        r.cellGradients(f.rho, f.U, f.p);

        const word what(s.first() + '/' + s.second());
        const vectorField gRho(fvc::grad(f.rho)().primitiveField());
        const vectorField gP(fvc::grad(f.p)().primitiveField());
        EXPECT_EQ(nDiffering(r.gradRho().primitiveField(), gRho), 0)
            << what << ": grad(rho) of " << gRho.size() << " cells";
        EXPECT_EQ(nDiffering(r.gradP().primitiveField(), gP), 0)
            << what << ": grad(p) of " << gP.size() << " cells";
        if (s.second() != "upwind")
        {
            const tensorField gU(fvc::grad(f.U)().primitiveField());
            EXPECT_EQ(nDiffering(r.gradU().primitiveField(), gU), 0)
                << what << ": grad(U) of " << gU.size() << " cells";
        }
        // Not trivially equal: the gradients are not zero
        EXPECT_GT(max(mag(gRho)), 0) << what;
        EXPECT_GT(max(mag(gP)), 0) << what;
    }
}


TEST(MUSCLReconstruction, faceStatesAreBoundedAndFirstOrderAtExtrema)
{
    foamUnit::testCase tc("MUSCLReconstruction");
    writeSchemes(tc, "MUSCL", "MUSCLV");
    autoPtr<fvMesh> mesh = tc.blockMesh
    (
        {12, 1, 1},
        [](const vector& s) { return cmptMultiply(s, vector(12, 1, 1)); },
        {"left", "right", "sides", "sides", "sides", "sides"},
        {"patch", "patch", "patch", "patch", "patch", "patch"}
    );
    primitiveFields f(mesh());
    const scalarList values({1, 2, 4, 5, 3, 3, 3, 7, 7.5, 6, 2, 2.5});
    forAll(values, celli)
    {
        f.rho[celli] = values[celli];
    }
    f.rho.correctBoundaryConditions();

    MUSCLReconstruction r(mesh());
    MUSCLReconstruction::states L, R;
    r.reconstruct(f.rho, f.U, f.p, L, R);

    // Faces i | i+1 of the row (owner i, neighbour i + 1)
    const scalar tol = 1e-14;
    label nExtrema = 0;
    forAll(L.rho, facei)
    {
        const scalar a = values[facei];
        const scalar b = values[facei + 1];
        for (const scalar s : {L.rho[facei], R.rho[facei]})
        {
            EXPECT_GE(s, min(a, b) - tol) << "face " << facei;
            EXPECT_LE(s, max(a, b) + tol) << "face " << facei;
        }
        // Owner a local extremum (or flat): the owner side is a
        if (facei > 0 && (a - values[facei - 1])*(b - a) <= 0)
        {
            EXPECT_NEAR(L.rho[facei], a, tol) << "face " << facei;
            ++nExtrema;
        }
        if
        (
            facei + 2 < values.size()
         && (b - a)*(values[facei + 2] - b) <= 0
        )
        {
            EXPECT_NEAR(R.rho[facei], b, tol) << "face " << facei;
        }
    }
    EXPECT_GE(nExtrema, 4);
}


namespace
{

//- rho, U, p of calculated patch type (boundary values set by the caller)
struct calculatedFields
{
    volScalarField rho;
    volVectorField U;
    volScalarField p;

    explicit calculatedFields(const fvMesh& mesh)
    :
        rho
        (
            primitiveFields::io(mesh, "rho"), mesh,
            dimensionedScalar(dimDensity, Zero)
        ),
        U
        (
            primitiveFields::io(mesh, "U"), mesh,
            dimensionedVector(dimVelocity, Zero)
        ),
        p
        (
            primitiveFields::io(mesh, "p"), mesh,
            dimensionedScalar(dimPressure, Zero)
        )
    {}

    //- Every cell and boundary face value from f(x) [x in m]
    template<class RhoF, class UF, class PF>
    void set(const RhoF& fRho, const UF& fU, const PF& fP)
    {
        const fvMesh& mesh = rho.mesh();
        forAll(mesh.C(), celli)
        {
            const point& x = mesh.C()[celli];
            rho[celli] = fRho(x);
            U[celli] = fU(x);
            p[celli] = fP(x);
        }
        forAll(mesh.boundary(), patchi)
        {
            const vectorField& Cf = mesh.Cf().boundaryField()[patchi];
            forAll(Cf, facei)
            {
                rho.boundaryFieldRef()[patchi][facei] = fRho(Cf[facei]);
                U.boundaryFieldRef()[patchi][facei] = fU(Cf[facei]);
                p.boundaryFieldRef()[patchi][facei] = fP(Cf[facei]);
            }
        }
    }
};


//- A block of 6 x 5 x 3 hexahedra, 1 um on average, of the given map
autoPtr<fvMesh> micrometreBlock
(
    foamUnit::testCase& tc,
    const std::function<point(const vector&)>& map
)
{
    return tc.blockMesh
    (
        {6, 5, 3},
        map,
        {"sides", "sides", "sides", "sides", "sides", "sides"},
        {"patch", "patch", "patch", "patch", "patch", "patch"}
    );
}


//- The max and min over each cell and its internal-face neighbours
template<class Type>
void neighbourhoodBounds
(
    const fvMesh& mesh,
    const Field<Type>& v,
    Field<Type>& maxV,
    Field<Type>& minV
)
{
    maxV = v;
    minV = v;
    forAll(mesh.owner(), facei)
    {
        const label own = mesh.owner()[facei];
        const label nei = mesh.neighbour()[facei];
        maxV[own] = max(maxV[own], v[nei]);
        minV[own] = min(minV[own], v[nei]);
        maxV[nei] = max(maxV[nei], v[own]);
        minV[nei] = min(minV[nei], v[own]);
    }
}

} // End anonymous namespace


TEST(MUSCLReconstruction, multidimensionalLimitersReconstructALinearField)
{
    // An affine map (sheared in x-y and x-z: faces 20-35 deg
    // non-orthogonal), where the Gauss-linear gradient of a linear field
    // is exact: every face state is the field at the face centre, for
    // both sides (the limiter 1)
    for (const word scheme : {"BarthJespersen", "venkatakrishnan"})
    {
        foamUnit::testCase tc("MUSCLReconstruction");
        writeSchemes(tc, scheme, scheme);
        autoPtr<fvMesh> mesh = micrometreBlock
        (
            tc,
            [](const vector& s)
            {
                return 1e-6*point
                (
                    6*s.x() + 2.5*s.y() + 0.8*s.z(), 5*s.y(), 3*s.z()
                );
            }
        );
        calculatedFields f(mesh());
        const auto fRho = [](const point& x)
        {
            return 1000 + 3e7*x.x() - 2e7*x.y() + 1e7*x.z();
        };
        const auto fU = [](const point& x)
        {
            return vector
            (
                10 + 4e6*x.x() + 1e6*x.y(),
                -3 + 2e6*x.z(),
                5e6*x.y() - 1e6*x.x()
            );
        };
        const auto fP = [](const point& x)
        {
            return 1e5 + 4e12*x.y() + 1e12*x.x();
        };
        f.set(fRho, fU, fP);

        MUSCLReconstruction r(mesh());
        MUSCLReconstruction::states L, R;
        r.reconstruct(f.rho, f.U, f.p, L, R);

        const vectorField& Cf = mesh().Cf();
        label nNonOrthogonal = 0;
        forAll(L.rho, facei)
        {
            const point& x = Cf[facei];
            EXPECT_NEAR(L.rho[facei], fRho(x), 1e-10) << scheme << facei;
            EXPECT_NEAR(R.rho[facei], fRho(x), 1e-10) << scheme << facei;
            EXPECT_NEAR(L.p[facei], fP(x), 1e-4) << scheme << facei;
            EXPECT_NEAR(R.p[facei], fP(x), 1e-4) << scheme << facei;
            EXPECT_LT(mag(L.U[facei] - fU(x)), 1e-11) << scheme << facei;
            EXPECT_LT(mag(R.U[facei] - fU(x)), 1e-11) << scheme << facei;

            // Non-orthogonal faces: P-N more than 15 deg off the normal
            const point& P = mesh().C()[mesh().owner()[facei]];
            const point& N = mesh().C()[mesh().neighbour()[facei]];
            const vector d(N - P);
            const vector n(mesh().Sf()[facei]/mesh().magSf()[facei]);
            nNonOrthogonal += (d & n)/mag(d) < std::cos(15*M_PI/180) ? 1 : 0;
        }
        EXPECT_GT(nNonOrthogonal, 50) << scheme;
    }
}


TEST(MUSCLReconstruction, multidimensionalLimitersBoundAStepOnASkewedMesh)
{
    // A non-affine map (cells of different shapes, faces skewed and
    // non-orthogonal) with a step across it, oblique to the grid: every
    // face state within the min/max of its cell and the cell's face
    // neighbours (the Venkatakrishnan limiter to within its eps, about
    // (5 um)^1.5 = 1e-8 here), where the unlimited extrapolation to the
    // face centres is outside on many faces
    const auto map = [](const vector& s)
    {
        return 1e-6*point
        (
            6*s.x() + 1.2*std::sin(3.0*s.y())*(0.5 + s.x()) + 0.5*s.z(),
            5*s.y() + 0.9*s.x()*s.x() + 0.4*std::sin(4.0*s.x())*s.y(),
            3*s.z() + 0.5*s.x()*s.y()
        );
    };
    const auto step = [](const point& x)
    {
        return x.x() + 0.6*x.y() - 0.3*x.z() > 4.1e-6 ? 1.0 : 0.0;
    };
    for (const word scheme : {"BarthJespersen", "venkatakrishnan"})
    {
        foamUnit::testCase tc("MUSCLReconstruction");
        writeSchemes(tc, scheme, scheme);
        autoPtr<fvMesh> mesh = micrometreBlock(tc, map);
        calculatedFields f(mesh());
        f.set
        (
            [&step](const point& x)
            {
                return 1000 + 2e7*x.y() + 300*step(x);
            },
            [&step](const point& x)
            {
                return vector
                (
                    -40*step(x) + 3e6*x.x(), 25*step(x), 5e6*x.y()*step(x)
                );
            },
            [&step](const point& x)
            {
                return 1e5 + 5e7*step(x) + 1e12*x.x();
            }
        );

        MUSCLReconstruction r(mesh());
        MUSCLReconstruction::states L, R;
        r.reconstruct(f.rho, f.U, f.p, L, R);

        scalarField maxRho, minRho, maxP, minP;
        vectorField maxU, minU;
        neighbourhoodBounds(mesh(), f.rho.primitiveField(), maxRho, minRho);
        neighbourhoodBounds(mesh(), f.p.primitiveField(), maxP, minP);
        neighbourhoodBounds(mesh(), f.U.primitiveField(), maxU, minU);

        // The unlimited face-centre extrapolation, for the check that the
        // bounds bite
        const volVectorField gradRho(fvc::grad(f.rho));
        const volVectorField gradP(fvc::grad(f.p));
        const volTensorField gradU(fvc::grad(f.U));

        const vectorField& Cf = mesh().Cf();
        const vectorField& C = mesh().C();
        const scalar tolRho = 1e-7;
        const scalar tolP = 1e-5;
        const scalar tolU = 1e-7;
        label nUnbounded = 0;
        forAll(L.rho, facei)
        {
            for (const label c : {mesh().owner()[facei],
                mesh().neighbour()[facei]})
            {
                const bool own = (c == mesh().owner()[facei]);
                const scalar rhoF = own ? L.rho[facei] : R.rho[facei];
                const scalar pF = own ? L.p[facei] : R.p[facei];
                const vector UF = own ? L.U[facei] : R.U[facei];
                EXPECT_LE(rhoF, maxRho[c] + tolRho) << scheme << facei;
                EXPECT_GE(rhoF, minRho[c] - tolRho) << scheme << facei;
                EXPECT_LE(pF, maxP[c] + tolP) << scheme << facei;
                EXPECT_GE(pF, minP[c] - tolP) << scheme << facei;
                for (direction d = 0; d < vector::nComponents; ++d)
                {
                    EXPECT_LE(UF[d], maxU[c][d] + tolU) << scheme << facei;
                    EXPECT_GE(UF[d], minU[c][d] - tolU) << scheme << facei;
                }

                const vector dx(Cf[facei] - C[c]);
                const scalar rhoX = f.rho[c] + (dx & gradRho[c]);
                const scalar pX = f.p[c] + (dx & gradP[c]);
                const vector UX = f.U[c] + (dx & gradU[c]);
                const bool out =
                    rhoX > maxRho[c] + 1 || rhoX < minRho[c] - 1
                 || pX > maxP[c] + 1e5 || pX < minP[c] - 1e5
                 || cmptMax(UX - maxU[c]) > 0.1
                 || cmptMin(UX - minU[c]) < -0.1;
                nUnbounded += out ? 1 : 0;
            }
        }
        EXPECT_GT(nUnbounded, 20) << scheme;
    }
}


TEST(MUSCLReconstruction, leastSquaresGradientsAreExactOnASkewedMesh)
{
    // The non-affine map of the step test (cells of different shapes,
    // faces skewed and non-orthogonal) with linear fields: the least-
    // squares cell gradients are the fields' gradients (to rounding),
    // pointCellsLeastSquares' in every cell, leastSquares' in the cells
    // without a boundary face (at a boundary face OpenFOAM v1912's
    // fvPatch::delta is the normal projection of x_f - x_P, so its
    // gradient there is not exact where the boundary is skewed); Gauss
    // linear's are not, interior cells included (its face value is the
    // field where P-N crosses the face, not at the face centre)
    const auto map = [](const vector& s)
    {
        return 1e-6*point
        (
            6*s.x() + 1.2*std::sin(3.0*s.y())*(0.5 + s.x()) + 0.5*s.z(),
            5*s.y() + 0.9*s.x()*s.x() + 0.4*std::sin(4.0*s.x())*s.y(),
            3*s.z() + 0.5*s.x()*s.y()
        );
    };
    const vector gRho(3e7, -2e7, 1e7);
    const tensor gU(4e6, 0, -1e6, 1e6, 0, 5e6, 0, 2e6, 0);
    const vector gP(1e12, 4e12, 0);
    const auto fRho = [&gRho](const point& x) { return 1000 + (gRho & x); };
    const auto fU = [&gU](const point& x)
    {
        return vector(10, -3, 0) + (x & gU);
    };
    const auto fP = [&gP](const point& x) { return 1e5 + (gP & x); };

    // Largest relative gradient error of rho, U, p over the cells
    // without a boundary face (interior) and over all cells
    struct errors { scalar interior, all; };
    const auto run = [&](const std::string& grad)
    {
        foamUnit::testCase tc("MUSCLReconstruction");
        writeSchemes(tc, "MUSCL", "MUSCLV", grad);
        autoPtr<fvMesh> mesh = micrometreBlock(tc, map);
        calculatedFields f(mesh());
        f.set(fRho, fU, fP);
        MUSCLReconstruction r(mesh());
        MUSCLReconstruction::states L, R;
        r.reconstruct(f.rho, f.U, f.p, L, R);

        boolList boundaryCell(mesh().nCells(), false);
        for (label facei = mesh().nInternalFaces();
            facei < mesh().nFaces(); ++facei)
        {
            boundaryCell[mesh().faceOwner()[facei]] = true;
        }
        errors e{0, 0};
        label nInterior = 0;
        forAll(mesh().C(), celli)
        {
            const scalar ec = max
            (
                max
                (
                    mag(r.gradRho()[celli] - gRho)/mag(gRho),
                    mag(r.gradU()[celli] - gU)/mag(gU)
                ),
                mag(r.gradP()[celli] - gP)/mag(gP)
            );
            e.all = max(e.all, ec);
            if (!boundaryCell[celli])
            {
                e.interior = max(e.interior, ec);
                ++nInterior;
            }
        }
        EXPECT_EQ(nInterior, 4*3*1);
        return e;
    };

    const errors ls = run("leastSquares");
    EXPECT_LT(ls.interior, 1e-12);
    const errors pc = run("pointCellsLeastSquares");
    EXPECT_LT(pc.interior, 1e-12);
    EXPECT_LT(pc.all, 1e-12);
    const errors gauss = run("Gauss linear");
    EXPECT_GT(gauss.interior, 0.02);
}


TEST(MUSCLReconstruction, refusedSchemeNamesTheFileEntryAndValidNames)
{
    {
        // A scalar limiter for U limits |U|^2, not the V scheme's jump
        const std::string m = refusal("MUSCL", "MUSCL");
        for (const std::string s : {"system/fvSchemes", "reconstruct(U)",
            "'MUSCL'", "MUSCLV", "vanLeerV", "upwind", "BarthJespersen",
            "venkatakrishnan"})
        {
            EXPECT_NE(m.find(s), std::string::npos)
                << "no '" << s << "' in: " << m;
        }
    }
    {
        const std::string m = refusal("linear", "MUSCLV");
        for (const std::string s : {"system/fvSchemes", "reconstruct(rho)",
            "'linear'", "vanAlbada", "Minmod"})
        {
            EXPECT_NE(m.find(s), std::string::npos)
                << "no '" << s << "' in: " << m;
        }
    }
    {
        const std::string m = refusal("limitedLinear 1", "MUSCLV");
        EXPECT_NE(m.find("'limitedLinear 1'"), std::string::npos) << m;
    }
    {
        const std::string m =
            refusal("MUSCL", "MUSCLV", "cellLimited Gauss linear 1");
        for (const std::string s : {"system/fvSchemes", "grad(rho)",
            "'cellLimited Gauss linear 1'", "(Gauss linear)",
            "(leastSquares)", "(pointCellsLeastSquares)"})
        {
            EXPECT_NE(m.find(s), std::string::npos)
                << "no '" << s << "' in: " << m;
        }
    }
}


TEST(MUSCLReconstruction, cellGradientsInTwoHalvesAsInOne)
{
    // startCellGradients, the internal faces, finishCellGradients (the
    // processor exchange overlapping the face loop, as riemannFlux::fluxes
    // makes it) give the states of cellGradients + reconstruct bit for bit
    foamUnit::testCase tc("MUSCLReconstruction");
    writeSchemes(tc, "vanLeer", "vanLeerV");
    autoPtr<fvMesh> mesh = tc.wedgeMesh();
    const primitiveFields f(mesh());
    const label nFaces = mesh().nInternalFaces();

    MUSCLReconstruction one(mesh());
    MUSCLReconstruction::states L1, R1;
    one.reconstruct(f.rho, f.U, f.p, L1, R1);

    MUSCLReconstruction halves(mesh());
    MUSCLReconstruction::states L2, R2;
    halves.startCellGradients(f.rho, f.U, f.p);
    halves.reconstruct(0, nFaces, f.rho, f.U, f.p, L2, R2);
    halves.finishCellGradients();

    EXPECT_TRUE(L1.rho == L2.rho);
    EXPECT_TRUE(R1.rho == R2.rho);
    EXPECT_TRUE(L1.U == L2.U);
    EXPECT_TRUE(R1.U == R2.U);
    EXPECT_TRUE(L1.p == L2.p);
    EXPECT_TRUE(R1.p == R2.p);

    // A finish without a start and a second start before the finish are
    // errors (stale neighbour gradients otherwise)
    EXPECT_THROW(halves.finishCellGradients(), Foam::error);
    halves.startCellGradients(f.rho, f.U, f.p);
    EXPECT_THROW
    (
        halves.startCellGradients(f.rho, f.U, f.p), Foam::error
    );
    halves.finishCellGradients();
}


TEST(MUSCLReconstruction, faceFrameReconstructsALinearField)
{
    // A graded Cartesian block (every face centre on its cells' line, the
    // Gauss-linear gradient of a linear field exact): MUSCL on both parts
    // gives the field at the face centre on both sides (r = 1, limiter 1);
    // with an upwind tangential part the normal component is still exact
    // and the tangential part is the upwind cell's
    for (const word tangential : {"MUSCL", "upwind"})
    {
        foamUnit::testCase tc("MUSCLReconstruction");
        writeSchemes(tc, "MUSCL", "normalTangential MUSCL " + tangential);
        autoPtr<fvMesh> mesh = micrometreBlock
        (
            tc,
            [](const vector& s)
            {
                return 1e-6*point
                (
                    6*std::pow(s.x(), 1.4), 5*std::pow(s.y(), 0.8),
                    3*s.z()*(0.6 + 0.4*s.z())
                );
            }
        );
        calculatedFields f(mesh());
        const auto fU = [](const point& x)
        {
            return vector
            (
                10 + 4e6*x.x() + 1e6*x.y() - 3e6*x.z(),
                -3 + 2e6*x.z() - 5e6*x.x(),
                5e6*x.y() - 1e6*x.x() + 2e6*x.z()
            );
        };
        f.set
        (
            [](const point& x) { return 1000 + 3e7*x.x(); },
            fU,
            [](const point& x) { return 1e5 + 4e12*x.y(); }
        );

        MUSCLReconstruction r(mesh());
        EXPECT_TRUE(r.UScheme().faceFrame);
        MUSCLReconstruction::states L, R;
        r.reconstruct(f.rho, f.U, f.p, L, R);

        const vectorField& Cf = mesh().Cf();
        label nTangential = 0;
        label nUnequalCells = 0;
        forAll(L.U, facei)
        {
            const vector n(mesh().Sf()[facei]/mesh().magSf()[facei]);
            const vector Uf(fU(Cf[facei]));
            const label own = mesh().owner()[facei];
            const label nei = mesh().neighbour()[facei];
            for (const vector& s : {L.U[facei], R.U[facei]})
            {
                EXPECT_NEAR(s & n, Uf & n, 1e-11) << tangential << facei;
            }
            const auto tang = [&n](const vector& u) { return u - (u & n)*n; };
            if (tangential == "MUSCL")
            {
                EXPECT_LT(mag(L.U[facei] - Uf), 1e-11) << facei;
                EXPECT_LT(mag(R.U[facei] - Uf), 1e-11) << facei;
            }
            else
            {
                EXPECT_LT(mag(tang(L.U[facei]) - tang(f.U[own])), 1e-12)
                    << facei;
                EXPECT_LT(mag(tang(R.U[facei]) - tang(f.U[nei])), 1e-12)
                    << facei;
            }
            nTangential += mag(tang(Uf)) > 1 ? 1 : 0;
            nUnequalCells += mag(tang(f.U[own] - f.U[nei])) > 0.1 ? 1 : 0;
        }
        // Not trivially so: tangential velocities and their jumps on
        // most faces (the test distinguishes the two tangential schemes)
        EXPECT_GT(nTangential, L.U.size()/2) << tangential;
        EXPECT_GT(nUnequalCells, L.U.size()/2) << tangential;
    }
}


TEST(MUSCLReconstruction, faceFrameBoundsAnObliqueStep)
{
    // A uniform row of 12 cells turned so that its face normals are
    // n = (2, 1, 2)/3: the cells' normal velocities 1 2 4 5 3 3 3 7 7.5 6
    // 2 2.5 [m/s] and a tangential part with a step. MUSCL on the normal
    // component: each face's normal state between the two cells' (TVD on
    // a uniform row), the upwind cell's at an extremum; upwind on the
    // tangential part: the cell's own. A purely normal velocity gives
    // MUSCLV's states (one limiter along the jump, here along n)
    const vector n(vector(2, 1, 2)/3);
    const vector t1(vector(1, 2, -2)/3);
    const vector t2(n ^ t1);
    const auto map = [&](const vector& s)
    {
        return 1e-6*(12*s.x()*n + s.y()*t1 + s.z()*t2);
    };
    const scalarList normal({1, 2, 4, 5, 3, 3, 3, 7, 7.5, 6, 2, 2.5});

    for (const bool withTangential : {true, false})
    {
        vectorField faceFrameL, faceFrameR;
        for (const word scheme : {"normalTangential MUSCL upwind", "MUSCLV"})
        {
            foamUnit::testCase tc("MUSCLReconstruction");
            writeSchemes(tc, "MUSCL", scheme);
            autoPtr<fvMesh> mesh = tc.blockMesh
            (
                {12, 1, 1}, map,
                {"left", "right", "sides", "sides", "sides", "sides"},
                {"patch", "patch", "patch", "patch", "patch", "patch"}
            );
            primitiveFields f(mesh());
            forAll(normal, celli)
            {
                const scalar tangent =
                    withTangential ? (celli < 6 ? 3.0 : -8.0) : 0.0;
                f.U[celli] =
                    normal[celli]*n + tangent*t1 + 0.5*tangent*celli*t2;
            }
            f.U.correctBoundaryConditions();

            MUSCLReconstruction r(mesh());
            MUSCLReconstruction::states L, R;
            r.reconstruct(f.rho, f.U, f.p, L, R);
            ASSERT_EQ(L.U.size(), normal.size() - 1);

            if (scheme == "MUSCLV")
            {
                if (!withTangential)
                {
                    forAll(L.U, facei)
                    {
                        EXPECT_LT(mag(L.U[facei] - faceFrameL[facei]), 1e-13)
                            << facei;
                        EXPECT_LT(mag(R.U[facei] - faceFrameR[facei]), 1e-13)
                            << facei;
                    }
                }
                continue;
            }
            faceFrameL = L.U;
            faceFrameR = R.U;

            const scalar tol = 1e-13;
            label nExtrema = 0;
            label nSecondOrder = 0;
            forAll(L.U, facei)
            {
                // The mesh's face normal is n (owner to neighbour)
                const vector nf
                (
                    mesh().Sf()[facei]/mesh().magSf()[facei]
                );
                ASSERT_LT(mag(nf - n), 1e-12);
                const scalar a = normal[facei];
                const scalar b = normal[facei + 1];
                for (const vector& s : {L.U[facei], R.U[facei]})
                {
                    EXPECT_GE(s & n, min(a, b) - tol) << "face " << facei;
                    EXPECT_LE(s & n, max(a, b) + tol) << "face " << facei;
                }
                EXPECT_LT
                (
                    mag
                    (
                        (L.U[facei] - (L.U[facei] & n)*n)
                      - (f.U[facei] - (f.U[facei] & n)*n)
                    ),
                    tol
                ) << "face " << facei;
                EXPECT_LT
                (
                    mag
                    (
                        (R.U[facei] - (R.U[facei] & n)*n)
                      - (f.U[facei + 1] - (f.U[facei + 1] & n)*n)
                    ),
                    tol
                ) << "face " << facei;
                if (facei > 0 && (a - normal[facei - 1])*(b - a) <= 0)
                {
                    EXPECT_NEAR(L.U[facei] & n, a, tol) << "face " << facei;
                    ++nExtrema;
                }
                nSecondOrder += mag((L.U[facei] & n) - a) > 0.1 ? 1 : 0;
            }
            EXPECT_GE(nExtrema, 4);
            EXPECT_GE(nSecondOrder, 3);
        }
    }
}


TEST(MUSCLReconstruction, characteristicReconstructsALinearFieldAsMUSCL)
{
    // The sheared (affine) mesh of the multidimensional test, where the
    // Gauss-linear gradient of a linear field is exact and every limiter's
    // r is 1: the characteristic variables, a linear map of the
    // primitive ones, are linear too, so characteristic MUSCL MUSCL gives
    // the primitive MUSCL / MUSCLV states (to rounding), with a sound
    // speed that varies from cell to cell
    const auto map = [](const vector& s)
    {
        return 1e-6*point(6*s.x() + 2.5*s.y() + 0.8*s.z(), 5*s.y(), 3*s.z());
    };
    const auto fRho = [](const point& x)
    {
        return 1000 + 3e7*x.x() - 2e7*x.y() + 1e7*x.z();
    };
    const auto fU = [](const point& x)
    {
        return vector
        (
            10 + 4e6*x.x() + 1e6*x.y(), -3 + 2e6*x.z(), 5e6*x.y() - 1e6*x.x()
        );
    };
    const auto fP = [](const point& x)
    {
        return 1e5 + 4e12*x.y() + 1e12*x.x();
    };

    MUSCLReconstruction::states L[2], R[2];
    const std::string schemes[2][2] =
    {
        {"MUSCL", "MUSCLV"}, {"MUSCL", "characteristic MUSCL MUSCL"}
    };
    for (label k = 0; k < 2; ++k)
    {
        foamUnit::testCase tc("MUSCLReconstruction");
        writeSchemes(tc, schemes[k][0], schemes[k][1]);
        autoPtr<fvMesh> mesh = micrometreBlock(tc, map);
        calculatedFields f(mesh());
        f.set(fRho, fU, fP);
        volScalarField c
        (
            primitiveFields::io(mesh(), "c"), mesh(),
            dimensionedScalar("c", dimVelocity, 1500)
        );
        forAll(c, celli)
        {
            c[celli] = 1480 + 2e7*mesh().C()[celli].x();
        }
        MUSCLReconstruction r(mesh());
        r.soundSpeed(c);
        r.reconstruct(f.rho, f.U, f.p, L[k], R[k]);
    }
    ASSERT_EQ(L[0].rho.size(), L[1].rho.size());
    forAll(L[0].rho, facei)
    {
        EXPECT_NEAR(L[1].rho[facei], L[0].rho[facei], 1e-10) << facei;
        EXPECT_NEAR(R[1].rho[facei], R[0].rho[facei], 1e-10) << facei;
        EXPECT_NEAR(L[1].p[facei], L[0].p[facei], 1e-6) << facei;
        EXPECT_NEAR(R[1].p[facei], R[0].p[facei], 1e-6) << facei;
        EXPECT_LT(mag(L[1].U[facei] - L[0].U[facei]), 1e-11) << facei;
        EXPECT_LT(mag(R[1].U[facei] - R[0].U[facei]), 1e-11) << facei;
    }
}


TEST(MUSCLReconstruction, characteristicLimitsOnlyTheJumpingWaves)
{
    // A 1D Riemann problem's data on a uniform row of 12 cells, along x
    // and turned so that the face normals are n = (2, 1, 2)/3: rho 1000
    // kg/m^3, c 1500 m/s (Z = 1.5e6 kg/m^2/s), the wave against n w1 = p -
    // Z u_n linear, the wave along n w2 = p + Z u_n linear with a 50 MPa
    // step (a captured shock), so that p, u_n and w3 = rho - p/c^2 jump
    // too, and a tangential velocity with a step. With characteristic
    // MUSCL upwind: w1 is second order across the step (its face states
    // the linear interpolant, at every face whose cells have interior
    // neighbours), w2 and w3 between their two cells' values (TVD on a
    // uniform row), the tangential part the cell's own. The primitive
    // limiter (MUSCL, normalTangential MUSCL upwind) cuts w1 at the step
    const scalar rho0 = 1000;
    const scalar c0 = 1500;
    const scalar Z = rho0*c0;
    const vector n(vector(2, 1, 2)/3);
    const vector t1(vector(1, 2, -2)/3);
    const vector t2(n ^ t1);
    const label nCells = 12;
    const auto w1 = [](const label i) { return 2e6 + 3e5*(i + 0.5); };
    const auto w2 = [](const label i)
    {
        return 1e6 - 1e5*(i + 0.5) + (i >= 6 ? 5e7 : 0.0);
    };

    for (const bool turned : {false, true})
    {
        const vector e1(turned ? n : vector(1, 0, 0));
        const vector e2(turned ? t1 : vector(0, 1, 0));
        const vector e3(turned ? t2 : vector(0, 0, 1));
        scalarList w1Jump(2, Zero);
        for (const word scheme :
            {"characteristic MUSCL upwind", "normalTangential MUSCL upwind"})
        {
            const bool characteristic = (scheme == "characteristic MUSCL upwind");
            foamUnit::testCase tc("MUSCLReconstruction");
            writeSchemes(tc, "MUSCL", scheme);
            autoPtr<fvMesh> mesh = tc.blockMesh
            (
                {nCells, 1, 1},
                [&](const vector& s)
                {
                    return nCells*s.x()*e1 + s.y()*e2 + s.z()*e3;
                },
                {"left", "right", "sides", "sides", "sides", "sides"},
                {"patch", "patch", "patch", "patch", "patch", "patch"}
            );
            primitiveFields f(mesh());
            volScalarField c
            (
                primitiveFields::io(mesh(), "c"), mesh(),
                dimensionedScalar("c", dimVelocity, c0)
            );
            for (label i = 0; i < nCells; ++i)
            {
                f.rho[i] = rho0;
                f.p[i] = 0.5*(w1(i) + w2(i));
                f.U[i] =
                    (w2(i) - w1(i))/(2*Z)*e1 + (i < 6 ? 3.0 : -8.0)*e2;
            }
            f.rho.correctBoundaryConditions();
            f.U.correctBoundaryConditions();
            f.p.correctBoundaryConditions();

            MUSCLReconstruction r(mesh());
            r.soundSpeed(c);
            MUSCLReconstruction::states L, R;
            r.reconstruct(f.rho, f.U, f.p, L, R);
            ASSERT_EQ(L.rho.size(), nCells - 1);

            // The face states' characteristic variables (Z, c uniform)
            const auto w = [&](const scalar rho, const vector& U, const scalar p)
            {
                return vector(p - Z*(U & e1), p + Z*(U & e1), rho - p/sqr(c0));
            };
            for (label facei = 0; facei < nCells - 1; ++facei)
            {
                const vector nf(mesh().Sf()[facei]/mesh().magSf()[facei]);
                ASSERT_LT(mag(nf - e1), 1e-12);
                const vector a(w(f.rho[facei], f.U[facei], f.p[facei]));
                const vector b
                (
                    w(f.rho[facei + 1], f.U[facei + 1], f.p[facei + 1])
                );
                const vector sL(w(L.rho[facei], L.U[facei], L.p[facei]));
                const vector sR(w(R.rho[facei], R.U[facei], R.p[facei]));
                const scalar w1Face = 2e6 + 3e5*(facei + 1);
                if (facei == 5)
                {
                    w1Jump[characteristic] = mag(sL.x() - w1Face);
                }
                if (!characteristic)
                {
                    continue;
                }
                // w1: second order where the gradients are the interior
                // ones (faces 1 to 9); w2, w3: bounded (Pa, kg/m^3)
                if (facei >= 1 && facei <= nCells - 3)
                {
                    EXPECT_NEAR(sL.x(), w1Face, 1e-6) << turned << facei;
                    EXPECT_NEAR(sR.x(), w1Face, 1e-6) << turned << facei;
                }
                for (const vector& s : {sL, sR})
                {
                    EXPECT_GE(s.y(), min(a.y(), b.y()) - 1e-6) << facei;
                    EXPECT_LE(s.y(), max(a.y(), b.y()) + 1e-6) << facei;
                    EXPECT_GE(s.z(), min(a.z(), b.z()) - 1e-10) << facei;
                    EXPECT_LE(s.z(), max(a.z(), b.z()) + 1e-10) << facei;
                }
                // The tangential part: the cell's own (T upwind)
                const tensor T(I - sqr(e1));
                EXPECT_LT(mag((L.U[facei] - f.U[facei]) & T), 1e-12) << facei;
                EXPECT_LT(mag((R.U[facei] - f.U[facei + 1]) & T), 1e-12)
                    << facei;
            }
        }
        // At the step the primitive limiter cuts w1 (off its interpolant
        // by 5e4 Pa here, a sixth of its increment per cell, 3e5 Pa); the
        // characteristic one does not
        EXPECT_LT(w1Jump[1], 1e-6) << turned;
        EXPECT_GT(w1Jump[0], 2.5e4) << turned;
    }
}


TEST(MUSCLReconstruction, characteristicRefusesMismatchedSchemes)
{
    {
        const std::string m = refusal("vanLeer", "characteristic MUSCL upwind");
        for (const std::string s : {"system/fvSchemes", "reconstruct(rho)",
            "reconstruct(p)", "characteristic MUSCL upwind", "vanLeer"})
        {
            EXPECT_NE(m.find(s), std::string::npos)
                << "no '" << s << "' in: " << m;
        }
    }
    {
        const std::string m = refusal("MUSCL", "characteristic MUSCL");
        for (const std::string s : {"system/fvSchemes", "reconstruct(U)",
            "'characteristic MUSCL'", "characteristic N T", "vanAlbada"})
        {
            EXPECT_NE(m.find(s), std::string::npos)
                << "no '" << s << "' in: " << m;
        }
    }
    {
        // No sound speed given: an error, not a reconstruction with c = 0
        foamUnit::testCase tc("MUSCLReconstruction");
        writeSchemes(tc, "MUSCL", "characteristic MUSCL MUSCL");
        autoPtr<fvMesh> mesh = tc.wedgeMesh();
        const primitiveFields f(mesh());
        MUSCLReconstruction r(mesh());
        MUSCLReconstruction::states L, R;
        EXPECT_THROW(r.reconstruct(f.rho, f.U, f.p, L, R), Foam::error);
    }
}


TEST(MUSCLReconstruction, faceFrameRefusesAMalformedEntry)
{
    for
    (
        const std::string entry :
        {
            "normalTangential MUSCL", "normalTangential BarthJespersen upwind",
            "normalTangential MUSCLV upwind", "normalTangential MUSCL upwind 1"
        }
    )
    {
        const std::string m = refusal("MUSCL", entry);
        const std::string quoted("'" + entry + "'");
        for (const std::string& s : {std::string("system/fvSchemes"),
            std::string("reconstruct(U)"), quoted,
            std::string("normalTangential N T"),
            std::string("upwind MUSCL vanLeer Minmod vanAlbada")})
        {
            EXPECT_NE(m.find(s), std::string::npos)
                << "no '" << s << "' in: " << m;
        }
    }
    {
        // The face frame is offered in the plain refusal too
        const std::string m = refusal("MUSCL", "MUSCL");
        EXPECT_NE(m.find("normalTangential N T"), std::string::npos) << m;
    }
    {
        const std::string m =
            refusal
            (
                "upwind", "normalTangential upwind MUSCL",
                "cellLimited Gauss linear 1"
            );
        for (const std::string s : {"gradSchemes/grad(U)", "leastSquares",
            "Gauss linear"})
        {
            EXPECT_NE(m.find(s), std::string::npos)
                << "no '" << s << "' in: " << m;
        }
    }
}
