/*---------------------------------------------------------------------------*\
Description
    Unit tests of src/fluid (conservativeFluid, rungeKuttaScheme) with the
    Mie-Grueneisen water of rhoEThermo's Usage example:

    - the Shu-Osher weights of Euler, SSPRK2, SSPRK3; an unknown scheme is
      an error naming the entry;
    - fixed mesh, closed box with a 50 MPa diaphragm: total mass and total
      energy conserved to round-off over steps of every scheme (walls pass
      neither), no transverse momentum, and the time step of the Courant
      number gives a valid state;
    - moving mesh (the geometric conservation law): water at rest in a box
      whose interior points move arbitrarily stays at rest and uniform to
      round-off, the stage volumes match the mesh (gclError ~ 1e-16);
    - restoreOldState gives back the stored state bitwise;
    - the boundary conditions of each stage's state are evaluated at that
      state's time t_n + c_k dt (Euler 1; SSPRK2 1, 1; SSPRK3 1, 1/2, 1;
      restoreOldState's at t_n), on the fixed and the moving mesh, and
      the Time is back at the step's end bit for bit (a T patch field that
      records the Time's value at each evaluation; seen failing before the
      stage times: every evaluation at t_n + dt).
\*---------------------------------------------------------------------------*/

#include "conservativeFluid.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "Random.H"
#include "bitSet.H"
#include "foamTestCase.H"
#include "zeroGradientFvPatchFields.H"
#include "wedgeFvPatch.H"
#include "addToRunTimeSelectionTable.H"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <string>

using namespace Foam;

namespace Foam
{

//- zeroGradient that records the Time's value at each evaluation: the
//  times at which the fluid evaluates its boundary conditions
class timeRecorderFvPatchScalarField
:
    public zeroGradientFvPatchScalarField
{
public:

    TypeName("timeRecorder");

    //- The Time's values of the evaluations since the last clear()
    static DynamicList<scalar> times;

    timeRecorderFvPatchScalarField
    (
        const fvPatch& p,
        const DimensionedField<scalar, volMesh>& iF
    )
    :
        zeroGradientFvPatchScalarField(p, iF)
    {}

    timeRecorderFvPatchScalarField
    (
        const fvPatch& p,
        const DimensionedField<scalar, volMesh>& iF,
        const dictionary& dict
    )
    :
        zeroGradientFvPatchScalarField(p, iF, dict)
    {}

    timeRecorderFvPatchScalarField
    (
        const timeRecorderFvPatchScalarField& ptf,
        const fvPatch& p,
        const DimensionedField<scalar, volMesh>& iF,
        const fvPatchFieldMapper& mapper
    )
    :
        zeroGradientFvPatchScalarField(ptf, p, iF, mapper)
    {}

    timeRecorderFvPatchScalarField(const timeRecorderFvPatchScalarField& ptf)
    :
        zeroGradientFvPatchScalarField(ptf)
    {}

    timeRecorderFvPatchScalarField
    (
        const timeRecorderFvPatchScalarField& ptf,
        const DimensionedField<scalar, volMesh>& iF
    )
    :
        zeroGradientFvPatchScalarField(ptf, iF)
    {}

    virtual tmp<fvPatchScalarField> clone() const
    {
        return tmp<fvPatchScalarField>
        (
            new timeRecorderFvPatchScalarField(*this)
        );
    }

    virtual tmp<fvPatchScalarField> clone
    (
        const DimensionedField<scalar, volMesh>& iF
    ) const
    {
        return tmp<fvPatchScalarField>
        (
            new timeRecorderFvPatchScalarField(*this, iF)
        );
    }

    virtual void updateCoeffs()
    {
        if (updated())
        {
            return;
        }
        times.append(db().time().value());
        zeroGradientFvPatchScalarField::updateCoeffs();
    }
};

DynamicList<scalar> timeRecorderFvPatchScalarField::times;
makePatchTypeField(fvPatchScalarField, timeRecorderFvPatchScalarField);

} // End namespace Foam


namespace
{

//- A closed box of water (walls) on n cells, p in 0/p given as a function
//  of the cell centre x, T 300 K, at rest; timeScheme as given
struct fluidCase
{
    foamUnit::testCase tc;
    autoPtr<fvMesh> mesh;

    fluidCase(const Vector<label>& n, const word& timeScheme)
    :
        tc("conservativeFluid", 1e-10)
    {
        tc.writeThermophysicalProperties("mieGruneisen");
        tc.writeFile
        (
            "system/fvSolution",
            "FoamFile { version 2.0; format ascii; class dictionary;"
            " object fvSolution; }\n"
            "riemann { riemannSolver HLLC; timeScheme " + timeScheme + "; }\n"
        );
        tc.writeUniformField("p", dimPressure, 1e5, "zeroGradient");
        tc.writeUniformField("T", dimTemperature, 300, "zeroGradient");
        tc.writeFile
        (
            "0/U",
            "FoamFile { version 2.0; format ascii; class volVectorField;"
            " object U; }\n"
            "dimensions [0 1 -1 0 0 0 0];\n"
            "internalField uniform (0 0 0);\n"
            "boundaryField { \".*\" { type slip; } }\n"
        );
        mesh = tc.blockMesh
        (
            n,
            [](const vector& s) { return 1e-6*s; },
            {"walls", "walls", "walls", "walls", "walls", "walls"},
            {"wall", "wall", "wall", "wall", "wall", "wall"}
        );
    }
};


//- 0/p with the pressure p(x) [Pa] of each cell centre x (zeroGradient)
void writePressure
(
    const fluidCase& c,
    const std::function<scalar(const point&)>& p
)
{
    OStringStream os;
    os.precision(17);
    os  << "FoamFile { version 2.0; format ascii; class volScalarField;"
        << " object p; }" << nl
        << "dimensions [1 -1 -2 0 0 0 0];" << nl
        << "internalField nonuniform List<scalar> " << c.mesh->nCells()
        << " (";
    forAll(c.mesh->C(), i) os << ' ' << p(c.mesh->C()[i]);
    os  << " );" << nl
        << "boundaryField { \".*\" { type zeroGradient; } }" << nl;
    c.tc.writeFile("0/p", os.str());
}


scalar totalMass(const conservativeFluid& f)
{
    return gSum(f.mesh().V().field()*f.rho().primitiveField());
}


scalar totalEnergy(const conservativeFluid& f)
{
    return gSum(f.mesh().V().field()*f.rhoE().primitiveField());
}

} // End anonymous namespace


TEST(conservativeFluid, rungeKuttaWeights)
{
    const auto weights = [](const word& name)
    {
        dictionary d;
        d.add("timeScheme", name);
        const rungeKuttaScheme rk(d);
        List<scalar> a(rk.nStages());
        forAll(a, k) a[k] = rk.a(k);
        return a;
    };
    EXPECT_EQ(weights("Euler"), List<scalar>({0}));
    EXPECT_EQ(weights("SSPRK2"), List<scalar>({0, 0.5}));
    EXPECT_EQ(weights("SSPRK3"), List<scalar>({0, 0.75, 1.0/3.0}));
    EXPECT_EQ(rungeKuttaScheme(dictionary()).nStages(), 3);

    try
    {
        weights("RK4");
        FAIL() << "an unknown timeScheme was accepted";
    }
    catch (const Foam::IOerror& err)
    {
        const std::string msg(err.message());
        EXPECT_NE(msg.find("RK4"), std::string::npos) << msg;
        EXPECT_NE(msg.find("SSPRK3"), std::string::npos) << msg;
    }
}


TEST(conservativeFluid, closedBoxConservesMassAndEnergy)
{
    for (const word scheme : {"Euler", "SSPRK2", "SSPRK3"})
    {
        fluidCase c({16, 2, 1}, scheme);
        // A 50 MPa diaphragm at mid-length
        writePressure
        (
            c, [](const point& x) { return x.x() < 0.5e-6 ? 5e7 : 1e5; }
        );
        conservativeFluid fluid(c.tc.time(), c.mesh());
        rhoEThermo& thermo = fluid.thermo();

        const scalar m0 = totalMass(fluid);
        const scalar E0 = totalEnergy(fluid);

        Time& runTime = c.tc.time();
        for (label n = 0; n < 20; ++n)
        {
            fluid.fluxes();
            const scalar Co = fluid.courantNumber(runTime.deltaTValue());
            runTime.setDeltaT(0.5*runTime.deltaTValue()/max(Co, SMALL));
            ++runTime;
            fluid.storeOldState();
            fluid.step(runTime.deltaTValue());
            thermo.checkStates();
        }

        EXPECT_NEAR(totalMass(fluid), m0, 1e-13*m0) << scheme;
        EXPECT_NEAR(totalEnergy(fluid), E0, 1e-12*E0) << scheme;
        // The wave moved: not a trivial pass
        EXPECT_GT(gMax(mag(fluid.U().primitiveField())), 1) << scheme;
        EXPECT_LT
        (
            gMax(mag(fluid.rhoU().primitiveField().component(vector::Y))),
            1e-9*gMax(mag(fluid.rhoU().primitiveField()))
        ) << scheme;
    }
}


TEST(conservativeFluid, movingMeshKeepsRestStateUniform)
{
    fluidCase c({6, 5, 1}, "SSPRK3");
    fvMesh& mesh = c.mesh();
    conservativeFluid fluid(c.tc.time(), mesh);

    const scalar rho0 = fluid.rho()[0];
    const scalar rhoE0 = fluid.rhoE()[0];

    // The points off the x and y walls move by up to 2.5 % of a cell each
    // step, in x and y (the mesh is one cell thick in z: its z walls move
    // in their planes and sweep no volume)
    bitSet boundary(mesh.nPoints());
    forAll(mesh.points(), p)
    {
        const point& x = mesh.points()[p];
        boundary.set
        (
            p,
            x.x() < 1e-12 || x.x() > 1e-6 - 1e-12
         || x.y() < 1e-12 || x.y() > 1e-6 - 1e-12
        );
    }
    const scalarField Vstart(mesh.V().field());

    Time& runTime = c.tc.time();
    runTime.setDeltaT(1e-11);
    Random rnd(7);
    scalar worstGcl = 0;
    for (label n = 0; n < 10; ++n)
    {
        ++runTime;
        fluid.storeOldState();
        pointField newPoints(mesh.points());
        forAll(newPoints, p)
        {
            if (!boundary.test(p))
            {
                newPoints[p] +=
                    0.05e-6/6*vector
                    (
                        rnd.sample01<scalar>() - 0.5,
                        rnd.sample01<scalar>() - 0.5,
                        0
                    );
            }
        }
        mesh.movePoints(newPoints);
        ASSERT_TRUE(mesh.moving());
        worstGcl = max
        (
            worstGcl,
            returnReduce
            (
                fluid.aleStep(runTime.deltaTValue(), ""), maxOp<scalar>()
            )
        );
    }

    // The mesh did move: cell volumes changed by percents
    EXPECT_GT(gMax(mag(mesh.V().field() - Vstart)/Vstart), 1e-3);
    EXPECT_LT(worstGcl, 1e-13);
    EXPECT_LT(gMax(mag(fluid.U().primitiveField())), 1e-9);
    EXPECT_LT
    (
        gMax(mag(fluid.rho().primitiveField() - rho0)), 1e-12*rho0
    );
    EXPECT_LT
    (
        gMax(mag(fluid.rhoE().primitiveField() - rhoE0)), 1e-12*rhoE0
    );
}


TEST(conservativeFluid, restoreOldStateIsBitwise)
{
    fluidCase c({8, 1, 1}, "SSPRK3");
    writePressure(c, [](const point& x) { return 1e5 + 1e12*x.x(); });
    conservativeFluid fluid(c.tc.time(), c.mesh());
    const rhoEThermo& thermo = fluid.thermo();

    // The primitives of the stored state (p from the law: it differs from
    // the p read in 0/p by round-off)
    fluid.storeOldState();
    fluid.restoreOldState();
    const scalarField rho(fluid.rho().primitiveField());
    const vectorField rhoU(fluid.rhoU().primitiveField());
    const scalarField rhoE(fluid.rhoE().primitiveField());
    const scalarField p(thermo.p().primitiveField());

    Time& runTime = c.tc.time();
    runTime.setDeltaT(1e-11);
    ++runTime;
    fluid.fluxes();
    fluid.step(runTime.deltaTValue());
    ASSERT_NE(fluid.rho().primitiveField(), rho);

    fluid.restoreOldState();
    EXPECT_EQ(fluid.rho().primitiveField(), rho);
    EXPECT_EQ(fluid.rhoU().primitiveField(), rhoU);
    EXPECT_EQ(fluid.rhoE().primitiveField(), rhoE);
    EXPECT_EQ(thermo.p().primitiveField(), p);
}


TEST(conservativeFluid, boundaryAtStageTimes)
{
    typedef timeRecorderFvPatchScalarField recorder;
    const std::map<word, List<scalar>> stageTimes
    {
        {"Euler", {1}}, {"SSPRK2", {1, 1}}, {"SSPRK3", {1, 0.5, 1}}
    };
    for (const auto& scheme : stageTimes)
    {
        for (const bool moving : {false, true})
        {
            fluidCase c({4, 3, 1}, scheme.first);
            c.tc.writeUniformField
            (
                "T", dimTemperature, 300, "timeRecorder"
            );
            // p varies: the stages' states differ
            writePressure
            (
                c, [](const point& x) { return 1e5 + 1e12*x.x(); }
            );
            fvMesh& mesh = c.mesh();
            conservativeFluid fluid(c.tc.time(), mesh);
            ASSERT_EQ(fluid.rk().nStages(), scheme.second.size());
            forAll(scheme.second, k)
            {
                EXPECT_EQ(fluid.rk().c(k), scheme.second[k])
                    << scheme.first << " stage " << k;
            }

            Time& runTime = c.tc.time();
            runTime.setDeltaT(1e-11);
            for (label n = 0; n < 3; ++n)
            {
                ++runTime;
                const scalar tEnd = runTime.value();
                const scalar dt = runTime.deltaTValue();
                fluid.fluxes();
                fluid.storeOldState();
                recorder::times.clear();
                if (moving)
                {
                    // One interior point moves along x
                    pointField newPoints(mesh.points());
                    forAll(newPoints, p)
                    {
                        const point& x = newPoints[p];
                        if
                        (
                            x.x() > 1e-12 && x.x() < 1e-6 - 1e-12
                         && x.y() > 1e-12 && x.y() < 1e-6 - 1e-12
                        )
                        {
                            newPoints[p].x() += 1e-9*(n + 1);
                        }
                    }
                    mesh.movePoints(newPoints);
                    fluid.aleStep(dt, "");
                }
                else
                {
                    fluid.step(dt);
                }
                ASSERT_EQ(recorder::times.size(), scheme.second.size())
                    << scheme.first;
                forAll(scheme.second, k)
                {
                    EXPECT_NEAR
                    (
                        recorder::times[k],
                        tEnd - (1 - scheme.second[k])*dt,
                        1e-9*dt
                    ) << scheme.first << (moving ? " moving" : "")
                      << " step " << n << " stage " << k;
                }
                EXPECT_EQ(runTime.value(), tEnd) << scheme.first;

                // A repeated coupling pass starts from the state at t_n
                recorder::times.clear();
                fluid.restoreOldState();
                ASSERT_EQ(recorder::times.size(), 1);
                EXPECT_NEAR(recorder::times[0], tEnd - dt, 1e-9*dt)
                    << scheme.first;
                EXPECT_EQ(runTime.value(), tEnd) << scheme.first;
                if (moving)
                {
                    fluid.aleStep(dt, "");
                }
                else
                {
                    fluid.step(dt);
                }
            }
        }
    }
}


//- The viscous step on an axisymmetric wedge (the wedge mesh of the test
//  case: r 2-18 um, 5 deg): the wedge faces carry the hoop term's
//  (8/3) nu/r^2, not their (8/3) nu |Sf| deltaCoeffs/V, 1/theta^2 (525)
//  times stiffer. The step is that of the r-z faces alone, times at most
//  2 (the hoop term, below the r-z faces' rate at r >= 2 um on 1-3.6 um
//  cells); with the wedge faces as faces it was 14.6 times shorter
//  (1.06e-8 against the r-z faces' 1.55e-7 s: fails)
TEST(conservativeFluid, viscousStepOnAWedgeIsTheHoopTerms)
{
    foamUnit::testCase tc("conservativeFluid", 1e-10);
    tc.writeThermophysicalProperties("mieGruneisen");
    tc.writeFile
    (
        "system/fvSolution",
        "FoamFile { version 2.0; format ascii; class dictionary;"
        " object fvSolution; }\n"
        "riemann { riemannSolver HLLC; timeScheme SSPRK3; viscous true;"
        " mu 1e-3; }\n"
    );
    const std::string fields[3][4] =
    {
        {"p", "volScalarField", "[1 -1 -2 0 0 0 0]", "1e5"},
        {"T", "volScalarField", "[0 0 0 1 0 0 0]", "300"},
        {"U", "volVectorField", "[0 1 -1 0 0 0 0]", "(0 0 0)"}
    };
    for (const auto& f : fields)
    {
        tc.writeFile
        (
            "0/" + f[0],
            "FoamFile { version 2.0; format ascii; class " + f[1]
          + "; object " + f[0] + "; }\ndimensions " + f[2]
          + ";\ninternalField uniform " + f[3]
          + ";\nboundaryField { \".*\" { type zeroGradient; } bottom { type"
            " symmetryPlane; } \"front|back\" { type wedge; } }\n"
        );
    }
    autoPtr<fvMesh> meshPtr = tc.wedgeMesh();
    const fvMesh& mesh = meshPtr();
    conservativeFluid fluid(tc.time(), meshPtr());
    ASSERT_TRUE(fluid.viscous());

    // The r-z faces' rate per cell, 0.5 sum (8/3) nu |Sf| deltaCoeffs / V
    const scalarField& rho = fluid.rho().primitiveField();
    scalarField sum(mesh.nCells(), Zero);
    const scalar mu = 1e-3;
    forAll(mesh.owner(), facei)
    {
        const label o = mesh.owner()[facei], n = mesh.neighbour()[facei];
        const scalar s =
            (8.0/3.0)*mu/(0.5*(rho[o] + rho[n]))
           *mesh.magSf()[facei]*mesh.deltaCoeffs()[facei];
        sum[o] += s;
        sum[n] += s;
    }
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        if (isA<wedgeFvPatch>(patch))
        {
            continue;
        }
        forAll(patch, facei)
        {
            const label c = patch.faceCells()[facei];
            sum[c] +=
                (8.0/3.0)*mu/rho[c]*patch.magSf()[facei]
               *patch.deltaCoeffs()[facei];
        }
    }
    const scalar rzStep = 1/(0.5*gMax(sum/mesh.V().field()));
    const scalar step = fluid.viscousDeltaT(1);
    EXPECT_LE(step, rzStep*(1 + 1e-12));
    EXPECT_GE(step, 0.5*rzStep)
        << "the viscous step " << step << " s, the r-z faces' " << rzStep
        << " s";
}


TEST(conservativeFluid, timeMustBeTheMeshs)
{
    // The stages set the value of the Time the fluid is given: another
    // run's Time than the mesh's is refused
    fluidCase c({2, 1, 1}, "SSPRK3");
    foamUnit::testCase other("conservativeFluidOtherTime");
    try
    {
        conservativeFluid fluid(other.time(), c.mesh());
        FAIL() << "a Time other than the mesh's was accepted";
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        EXPECT_NE(msg.find("not the mesh's"), std::string::npos) << msg;
    }
}


// ************************************************************************* //
