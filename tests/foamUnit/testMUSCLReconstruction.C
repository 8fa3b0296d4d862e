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
    - a scheme it does not reproduce (a scalar limiter for U, a central
      scheme, a limiter with a coefficient, a gradient scheme other than
      Gauss linear) stops with an error naming system/fvSchemes, the entry
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
    const std::string& gradScheme = "Gauss linear"
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
        {"reconstruct\\(p\\) +MUSCL;", "reconstruct(p) " + scalarScheme}
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


TEST(MUSCLReconstruction, refusedSchemeNamesTheFileEntryAndValidNames)
{
    {
        // A scalar limiter for U limits |U|^2, not the V scheme's jump
        const std::string m = refusal("MUSCL", "MUSCL");
        for (const std::string s : {"system/fvSchemes", "reconstruct(U)",
            "'MUSCL'", "MUSCLV", "vanLeerV", "upwind"})
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
        const std::string m = refusal("MUSCL", "MUSCLV", "leastSquares");
        for (const std::string s : {"system/fvSchemes", "grad(rho)",
            "leastSquares", "Gauss linear"})
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
