/*---------------------------------------------------------------------------*\
Description
    Unit tests of src/fsi fluidSolidInteraction as a whole, on a tiny 1D
    coupled case built in a temporary folder (tests/fsi/pulseLayer shrunk):
    a water column of 20 cells (10 um, loaded face at x = 0, interface at
    x = 10 um, interfaceMotion) against a water-like solid layer of 10
    elements (10-15 um, rigid wall at 15 um, uniaxial strain), robin
    coupling with tolerance 1e-6. Each run loops as cellBlastFoam does
    (step, setDeltaT, write inside the write guard).

    - at rest (gauge pressure 0 on both sides) the steps keep the rest:
      fluid velocity, density change, solid displacement and coupling
      residual at round-off;
    - loaded (50 MPa in the water at t = 0): every step converges within
      the coupling tolerance in more than one and at most maxIter
      iterations, and coupling.dat reports those iterations, that residual
      and the convergence of each step;
    - the force balance of the interface: the fluid force on the wall
      (coupling.dat's interfaceForce, the momentum flux through the wall)
      equals the sum of the nodal forces the solid receives (the force
      map is conservative);
    - the geometric conservation error of each step (coupling.dat) is at
      round-off although the wall moves;
    - a restart from a write time (fluid fields and points, solid state in
      solid.h5, uniform/fsiState; a time name of 6 digits that does not
      hold the time exactly) continues bitwise: fields, points, solid
      state, time and time step, and the coupling.dat rows equal those of
      the uninterrupted run.
\*---------------------------------------------------------------------------*/

#include "fluidSolidInteraction.H"
#include "writeGuard.H"
#include "foamTestCase.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace Foam;

namespace
{

const scalar fluidLength = 10e-6;       // [m]
const scalar solidLength = 5e-6;        // [m]
const scalar couplingTolerance = 1e-6;  // [-]
const label maxIter = 30;

const std::string header
(
    "FoamFile { version 2.0; format ascii; class dictionary; object "
);

//- system/controlDict: time step from the Courant number, a write every
//  writeInterval steps; time names of 6 digits, which do not hold the
//  times (sums of time steps from an odd first one) exactly, as in a real
//  case: a restart must take its start time from uniform/time. endTime
//  given (> 0): the run ends there, its steps adjusted to end on it
std::string controlDictText
(
    const word& startFrom,
    const label writeInterval,
    const scalar endTime = 0
)
{
    std::ostringstream end;
    end.precision(17);
    if (endTime > 0)
    {
        end << "endTime " << endTime << ";\n"
            << "writeControl adjustableRunTime;\n"
            << "writeInterval " << endTime << ";\n";
    }
    else
    {
        // a nominal end the tests never reach (they step themselves):
        // its 1e11 solid steps are allowed (the solid's steps count in
        // foamTools::checkStepCount since fix19i)
        end << "endTime 1;\n"
            << "maxSteps 1e15;\n"
            << "writeControl timeStep;\n"
            << "writeInterval " << writeInterval << ";\n";
    }
    return header + "controlDict; }\n"
        "application cellBlastFoam;\n"
        "startFrom " + startFrom + ";\n"
        "startTime 0;\n"
        "stopAt endTime;\n"
        + end.str() +
        "deltaT 1.234567e-11;\n"
        "writeFormat ascii;\n"
        "writePrecision 17;\n"
        "timeFormat general;\n"
        "timePrecision 6;\n"
        "runTimeModifiable false;\n"
        "adjustTimeStep yes;\n"
        "maxCo 0.5;\n"
        "maxDeltaT 1e-9;\n";
}


//- The case files: fluid mesh, water at gauge pressure p [Pa] and rest
//  (ramp: rising linearly from 0 at the loaded face, held at 0, to p at
//  the interface, so that the wall force falls over the run), the solid
//  layer of solidCells elements, the coupling (solidSubcycles given if
//  > 0). shearVelocity > 0: the water viscous (mu = viscosity) and moving
//  along y at shearVelocity [m/s] past the solid at rest, whose nodes are
//  free along y but at the rigid wall (the no-slip wall's drag)
const scalar viscosity = 1e-3;          // [Pa s]
void writeCase
(
    foamUnit::testCase& tc,
    const scalar p,
    const label solidCells = 10,
    const label solidSubcycles = 0,
    const bool ramp = false,
    const scalar shearVelocity = 0
)
{
    const bool shear = shearVelocity > 0;
    std::ostringstream muText;
    muText.precision(17);
    muText<< " viscous true; mu " << viscosity << ";";
    tc.writeThermophysicalProperties("mieGruneisen");
    if (shear)
    {
        // the test case's schemes (upwind faces) with the viscous
        // stress's divergence, as the tutorials' fvSchemes
        tc.writeFile
        (
            "system/fvSchemes",
            header + "fvSchemes; }\n"
            "ddtSchemes { default Euler; }\n"
            "gradSchemes { default Gauss linear; }\n"
            "divSchemes { default none; div(tauMC) Gauss linear; }\n"
            "laplacianSchemes { default Gauss linear corrected; }\n"
            "interpolationSchemes { default linear; reconstruct(rho) upwind;"
            " reconstruct(U) upwind; reconstruct(p) upwind; }\n"
            "snGradSchemes { default corrected; }\n"
        );
    }
    tc.writeFile
    (
        "system/fvSolution",
        header + "fvSolution; }\n"
        "riemann { riemannSolver HLLC; timeScheme SSPRK3;"
      + (shear ? muText.str() : std::string()) + " }\n"
    );
    std::ostringstream pText;
    pText.precision(17);
    pText
        << "FoamFile { version 2.0; format ascii; class volScalarField;"
        << " object p; }\n"
        << "dimensions [1 -1 -2 0 0 0 0];\n";
    if (ramp)
    {
        pText<< "internalField nonuniform List<scalar> 20 (";
        for (label i = 0; i < 20; ++i)
        {
            pText<< ' ' << p*(i + 0.5)/20;
        }
        pText<< " );\n";
    }
    else
    {
        pText<< "internalField uniform " << p << ";\n";
    }
    pText
        << "boundaryField {\n"
        << "  loaded { type fixedValue; value uniform "
        << (ramp ? 0 : p) << "; }\n"
        << "  interface { type zeroGradient; }\n"
        << "  empty { type empty; }\n}\n";
    tc.writeFile("0/p", pText.str());
    tc.writeFile
    (
        "0/T",
        "FoamFile { version 2.0; format ascii; class volScalarField;"
        " object T; }\n"
        "dimensions [0 0 0 1 0 0 0];\n"
        "internalField uniform 293.15;\n"
        "boundaryField { loaded { type zeroGradient; }"
        " interface { type zeroGradient; } empty { type empty; } }\n"
    );
    std::ostringstream UText;
    UText.precision(17);
    UText<< "internalField uniform (0 " << shearVelocity << " 0);\n";
    tc.writeFile
    (
        "0/U",
        "FoamFile { version 2.0; format ascii; class volVectorField;"
        " object U; }\n"
        "dimensions [0 1 -1 0 0 0 0];\n"
      + UText.str() +
        "boundaryField { loaded { type zeroGradient; }"
        " interface { type movingWallVelocity; value uniform (0 0 0); }"
        " empty { type empty; } }\n"
    );
    tc.writeFile
    (
        "constant/solidProperties",
        header + "solidProperties; }\n"
        "mesh { type box; cells (" + std::to_string(solidCells) + " 1 1);"
        " min (10e-6 -0.5e-6 -0.5e-6); max (15e-6 0.5e-6 0.5e-6); }\n"
      + std::string
        (
            shear
          ? "fixed ((xmax 0) (xmax 1) (zmin 2) (zmax 2));\n"
          : "fixed ((xmax 0) (ymin 1) (ymax 1) (zmin 2) (zmax 2));\n"
        ) +
        "explicitSafety 0.8;\n"
        "materials { solid { rho0 1000; C10 0.5; volumetric mieGruneisen;"
        " C0 1450; s 1.99; Gamma0 0.1; Cv 4184; T0 293.15; } }\n"
    );
    tc.writeFile
    (
        "constant/fsiProperties",
        header + "fsiProperties; }\n"
        "interface { fluidPatch interface; solidFaceSet xmin;"
        " mapTolerance 0.1; motionDistance 5e-6; motionNearest 4; }\n"
        "coupling { scheme robin; maxIter 30; tolerance 1e-6;"
        " velocityScale 1e-2; onNonConvergence warn;"
      + (
            solidSubcycles > 0
          ? " solidSubcycles " + std::to_string(solidSubcycles) + ";"
          : std::string()
        )
      + " }\n"
    );
    tc.blockMesh
    (
        {20, 1, 1},
        [](const vector& s)
        {
            return vector
            (
                fluidLength*s.x(), 1e-6*(s.y() - 0.5), 1e-6*(s.z() - 0.5)
            );
        },
        {"loaded", "interface", "empty", "empty", "empty", "empty"},
        {"patch", "wall", "empty", "empty", "empty", "empty"}
    );
}


//- A run of the case as cellBlastFoam makes it: argList (-case), Time from
//  system/controlDict, the mesh of fluidSolidInteraction::newMesh, the
//  fluid, the coupling
class fsiRun
{
    autoPtr<Time> runTime_;
    autoPtr<dynamicFvMesh> mesh_;
    autoPtr<conservativeFluid> fluid_;
    autoPtr<fluidSolidInteraction> fsi_;

public:

    explicit fsiRun(const fileName& caseDir)
    {
        std::vector<std::string> words{"foamUnitTests", "-case", caseDir};
        std::vector<char*> argv;
        for (std::string& w : words)
        {
            argv.push_back(&w[0]);
        }
        int argc = int(argv.size());
        char** argvp = argv.data();
        // Never destroyed: argList's destructor ends the process
        // (UPstream::exit); it keeps copies of the arguments
        const argList& args = *new argList(argc, argvp);
        runTime_.reset(new Time(Time::controlDictName, args));
        mesh_ = fluidSolidInteraction::newMesh(args, runTime_());
        fluid_.reset(new conservativeFluid(runTime_(), mesh_()));
        fsi_.reset(new fluidSolidInteraction(mesh_(), fluid_()));
        if (!(runTime_().value() > 0))
        {
            fluid_().fluxes();
            fsi_().setDeltaT();
        }
    }

    ~fsiRun()
    {
        fsi_.clear();
        fluid_.clear();
        mesh_.clear();
        runTime_.clear();
    }

    Time& time() { return runTime_(); }
    const dynamicFvMesh& mesh() const { return mesh_(); }
    const conservativeFluid& fluid() const { return fluid_(); }
    const fluidSolidInteraction& fsi() const { return fsi_(); }

    //- One time step of cellBlastFoam's loop; false if the loop would end
    bool step()
    {
        Time& runTime = runTime_();
        if (!foamTools::writeGuard::run(runTime))
        {
            return false;
        }
        ++runTime;
        const scalar stepDeltaT = runTime.deltaTValue();
        fsi_().step();
        fluid_().thermo().checkStates();
        fsi_().setDeltaT();
        foamTools::writeGuard::write
        (
            runTime, [&]{ fsi_().write(stepDeltaT); }
        );
        return true;
    }

    //- The commit of the last write time (the loop's next condition)
    void finish()
    {
        foamTools::writeGuard::run(runTime_());
    }

    //- Total force the solid receives from its loads [N] (x y z)
    vector solidForce() const
    {
        const solid::Model& model = fsi_().solid().model();
        Eigen::VectorXd f = Eigen::VectorXd::Zero(model.nDisplacementDofs());
        for (const auto& c : model.contributions())
        {
            c->addForce(model, model.u, runTime_().value(), f, nullptr);
        }
        vector sum(Zero);
        const label dim = model.mesh().dim();
        for (label i = 0; i < f.size(); ++i)
        {
            sum[i % dim] += f[i];
        }
        return sum;
    }
};


//- A coupling.dat row: time dt iterations residual converged Fx Fy Fz
//  vMax gclError fluidWallWork solidExternalWork
struct couplingRow
{
    std::string text;
    scalar time, dt;
    label iterations;
    scalar residual;
    label converged;
    vector force;
    scalar vMax, gclError, fluidWork, solidWork;
};


std::vector<couplingRow> readCouplingLog(const fileName& file)
{
    std::ifstream is(file);
    EXPECT_TRUE(is.good()) << "cannot read " << file;
    std::vector<couplingRow> rows;
    std::string line;
    while (std::getline(is, line))
    {
        if (line.empty() || line[0] == '#')
        {
            continue;
        }
        std::istringstream ls(line);
        couplingRow r;
        r.text = line;
        ls  >> r.time >> r.dt >> r.iterations >> r.residual >> r.converged
            >> r.force.x() >> r.force.y() >> r.force.z() >> r.vMax
            >> r.gclError >> r.fluidWork >> r.solidWork;
        EXPECT_FALSE(ls.fail()) << "bad row of " << file << ": " << line;
        rows.push_back(r);
    }
    return rows;
}


//- Largest |a - b| over two fields
template<class Type>
scalar maxDiff(const Field<Type>& a, const Field<Type>& b)
{
    return gMax(mag(a - b));
}


//- Bitwise equality of two fields (the first differing index, or -1)
template<class Type>
label firstDifference(const UList<Type>& a, const UList<Type>& b)
{
    if (a.size() != b.size())
    {
        return 0;
    }
    forAll(a, i)
    {
        if (std::memcmp(&a[i], &b[i], sizeof(Type)) != 0)
        {
            return i;
        }
    }
    return -1;
}


label firstDifference(const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
    return firstDifference
    (
        UList<scalar>(const_cast<scalar*>(a.data()), a.size()),
        UList<scalar>(const_cast<scalar*>(b.data()), b.size())
    );
}

} // End anonymous namespace


TEST(fluidSolidInteraction, stepsAtRestKeepRest)
{
    foamUnit::testCase tc("fluidSolidInteraction");
    writeCase(tc, 0);
    tc.writeFile("system/controlDict", controlDictText("startTime", 1000));
    fsiRun run(tc.dir());
    const scalarField rho0(run.fluid().rho().primitiveField());
    const scalarField rhoE0(run.fluid().rhoE().primitiveField());
    const scalar c = 1450;      // [m/s]

    for (label n = 0; n < 5; ++n)
    {
        ASSERT_TRUE(run.step());
        // Water at rest: no velocity, no compression; p = 0 gauge at
        // (rho0, e0) makes every pressure flux zero to round-off
        EXPECT_LE(gMax(mag(run.fluid().U().primitiveField())), 1e-12*c);
        EXPECT_LE
        (
            maxDiff(run.fluid().rho().primitiveField(), rho0),
            1e-13*gMax(rho0)
        );
        EXPECT_LE
        (
            maxDiff(run.fluid().rhoE().primitiveField(), rhoE0),
            1e-12*max(gMax(mag(rhoE0)), 1)
        );
        // Solid: no motion (displacement << 1e-12 of an element, 0.5 um)
        const auto& u = run.fsi().solid().displacement();
        const auto& v = run.fsi().solid().velocity();
        EXPECT_LE(u.cwiseAbs().maxCoeff(), 1e-12*0.5e-6);
        EXPECT_LE(v.cwiseAbs().maxCoeff(), 1e-12*c);
        EXPECT_TRUE(run.fsi().coupling().converged());
        // Less than 1 uPa on the 1 um^2 wall [N]
        EXPECT_LE(mag(run.solidForce()), 1e-18);
    }
    run.finish();
}


TEST(fluidSolidInteraction, couplingConvergesAsCouplingDatReports)
{
    foamUnit::testCase tc("fluidSolidInteraction");
    writeCase(tc, 5e7);
    tc.writeFile("system/controlDict", controlDictText("startTime", 1000));
    fsiRun run(tc.dir());

    std::vector<label> iterations;
    std::vector<scalar> residuals;
    for (label n = 0; n < 6; ++n)
    {
        ASSERT_TRUE(run.step());
        const couplingScheme& cs = run.fsi().coupling();
        EXPECT_TRUE(cs.converged()) << "step " << n + 1;
        EXPECT_LE(cs.residual(), couplingTolerance) << "step " << n + 1;
        // The 50 MPa load moves the interface: the first pass is not the
        // converged one
        EXPECT_GT(cs.iterations(), 1) << "step " << n + 1;
        EXPECT_LE(cs.iterations(), maxIter) << "step " << n + 1;
        iterations.push_back(cs.iterations());
        residuals.push_back(cs.residual());
    }
    run.finish();

    const std::vector<couplingRow> rows =
        readCouplingLog(tc.dir()/"postProcessing"/"fsi"/"0"/"coupling.dat");
    ASSERT_EQ(rows.size(), iterations.size());
    for (size_t i = 0; i < rows.size(); ++i)
    {
        EXPECT_EQ(rows[i].iterations, iterations[i]) << rows[i].text;
        EXPECT_EQ(rows[i].converged, 1) << rows[i].text;
        EXPECT_LE(rows[i].residual, couplingTolerance) << rows[i].text;
        // 10 significant digits in the file
        EXPECT_NEAR(rows[i].residual, residuals[i], 1e-9*residuals[i])
            << rows[i].text;
    }
}


TEST(fluidSolidInteraction, interfaceForceBalanceAndGeometricConservation)
{
    foamUnit::testCase tc("fluidSolidInteraction");
    writeCase(tc, 5e7);
    tc.writeFile("system/controlDict", controlDictText("startTime", 1000));
    fsiRun run(tc.dir());

    std::vector<vector> solidForces;
    for (label n = 0; n < 6; ++n)
    {
        ASSERT_TRUE(run.step());
        // The fluid force on the wall (momentum flux through its faces)
        const label patchi =
            run.mesh().boundaryMesh().findPatchID("interface");
        const vector fluidForce =
            gSum(run.fluid().phiU().boundaryField()[patchi]);
        const vector solidForce = run.solidForce();
        // About p A = 5e7 Pa x 1e-12 m^2 = 5e-5 N, along x
        EXPECT_GT(fluidForce.x(), 1e-5);
        EXPECT_LE
        (
            mag(solidForce - fluidForce), 1e-13*mag(fluidForce)
        ) << "fluid " << fluidForce.x() << " N, solid " << solidForce.x()
          << " N (x)";
        solidForces.push_back(solidForce);
    }
    run.finish();

    const std::vector<couplingRow> rows =
        readCouplingLog(tc.dir()/"postProcessing"/"fsi"/"0"/"coupling.dat");
    ASSERT_EQ(rows.size(), solidForces.size());
    for (size_t i = 0; i < rows.size(); ++i)
    {
        // coupling.dat's interfaceForce (10 digits) is what the solid got
        EXPECT_LE
        (
            mag(rows[i].force - solidForces[i]), 1e-9*mag(solidForces[i])
        ) << rows[i].text;
        // The wall moved (vMax > 0) and the ALE step kept the geometric
        // conservation law to round-off
        EXPECT_GT(rows[i].vMax, 0) << rows[i].text;
        EXPECT_LE(std::abs(rows[i].gclError), 1e-13) << rows[i].text;
    }
}


//- The viscous water moving along the wall: the no-slip wall's drag
//  reaches the solid. Water at rest in x, U_y = 1 m/s, the solid at rest:
//  the first step's tangential force on the wall is the Laplacian's
//  mu A U_y / (dx/2) (the wall cell's centre dx/2 from the wall,
//  movingWallVelocity's U = the wall's velocity, about 0 after one step),
//  mu 1e-3 Pa s, A 1 um^2, dx 0.5 um: 4e-9 N along +y; the solid receives
//  exactly the fluid's wall force (pressure's and viscous), coupling.dat
//  reports it, and over the steps the solid's y momentum grows by what the
//  fluid's loses (the fluid's only y flux is the wall's), but for the
//  first half step, where the solid's trapezoid starts from no load.
//  Without the viscous force in the load the solid gets no y force
//  (fails)
TEST(fluidSolidInteraction, viscousWallDragReachesTheSolid)
{
    foamUnit::testCase tc("fluidSolidInteraction");
    const scalar V = 1;                 // [m/s]
    writeCase(tc, 0, 10, 0, false, V);
    tc.writeFile("system/controlDict", controlDictText("startTime", 1000));
    fsiRun run(tc.dir());
    ASSERT_TRUE(run.fluid().viscous());
    const label patchi = run.mesh().boundaryMesh().findPatchID("interface");
    const scalar A = 1e-12, dx = fluidLength/20;
    const scalar drag = viscosity*A*V/(0.5*dx);
    const auto fluidMomentumY = [&run]()
    {
        return gSum
        (
            run.fluid().rhoU().primitiveField().component(vector::Y)
           *run.mesh().V().field()
        );
    };
    const auto solidMomentumY = [&run]()
    {
        const auto& v = run.fsi().solid().velocity();
        const auto& m = run.fsi().solid().lumpedMass();
        scalar sum = 0;
        for (label i = 1; i < v.size(); i += 3)
        {
            sum += m[i]*v[i];
        }
        return sum;
    };
    const scalar fluid0 = fluidMomentumY();
    EXPECT_NEAR(fluid0, 1000*V*fluidLength*A, 1e-3*1000*V*fluidLength*A);
    ASSERT_EQ(solidMomentumY(), 0);

    std::vector<vector> solidForces;
    for (label n = 0; n < 6; ++n)
    {
        ASSERT_TRUE(run.step());
        const vector viscous =
            gSum(run.fluid().wallViscousForce(patchi)());
        const vector fluidForce =
            gSum(run.fluid().phiU().boundaryField()[patchi]) + viscous;
        const vector solidForce = run.solidForce();
        if (n == 0)
        {
            EXPECT_NEAR(viscous.y(), drag, 0.02*drag)
                << "the first step's viscous wall force along y [N]";
        }
        EXPECT_GT(solidForce.y(), 0.5*drag) << "step " << n + 1;
        EXPECT_LE(mag(solidForce - fluidForce), 1e-12*mag(fluidForce))
            << "fluid y " << fluidForce.y() << " N, solid y "
            << solidForce.y() << " N";
        solidForces.push_back(solidForce);
    }
    const scalar lost = fluid0 - fluidMomentumY();
    const scalar gained = solidMomentumY();
    run.finish();

    const std::vector<couplingRow> rows =
        readCouplingLog(tc.dir()/"postProcessing"/"fsi"/"0"/"coupling.dat");
    ASSERT_EQ(rows.size(), solidForces.size());
    scalar trapezoid = 0;
    for (size_t i = 0; i < rows.size(); ++i)
    {
        EXPECT_LE
        (
            mag(rows[i].force - solidForces[i]), 1e-9*mag(solidForces[i])
        ) << rows[i].text;
        trapezoid +=
            0.5*rows[i].dt
           *((i > 0 ? solidForces[i - 1].y() : 0) + solidForces[i].y());
    }
    // The solid's y momentum is the trapezoidal integral of its load
    // (central difference), which starts from no load at t = 0; the
    // fluid's stages take the wall's drag from the start, mu A V/(dx/2)
    // at t = 0 (SSPRK3: about the trapezoid of each step's two ends).
    // What the fluid lost along y is what the solid gained plus the
    // first half step's drag, dt_1/2 x drag, to 1 %
    EXPECT_GT(lost, 0);
    EXPECT_NEAR(gained, trapezoid, 1e-6*trapezoid)
        << "solid y momentum " << gained << " kg m/s";
    const scalar start = 0.5*rows.front().dt*drag;
    EXPECT_NEAR(gained + start, lost, 0.01*lost)
        << "fluid y momentum lost " << lost << " kg m/s, solid's gained "
        << gained << " kg m/s, the first half step's drag " << start
        << " kg m/s";
}


//- What a run of the loaded case to its end time gives: per step the
//  coupled step, the solid's step before it and the solid substeps taken;
//  coupling.dat; at the end the solid state and the interface energies
struct endResult
{
    std::vector<scalar> dt, solidDt;
    std::vector<label> substeps;
    std::vector<couplingRow> rows;
    scalar time;
    Eigen::VectorXd u, v;
    scalar fluidWork, solidWork;
};


endResult runToEnd
(
    const label solidCells,
    const label solidSubcycles,
    const scalar endTime
)
{
    foamUnit::testCase tc("fluidSolidInteraction");
    writeCase(tc, 5e7, solidCells, solidSubcycles, true);
    tc.writeFile
    (
        "system/controlDict", controlDictText("startTime", 0, endTime)
    );
    endResult r;
    {
        fsiRun run(tc.dir());
        for (;;)
        {
            const scalar dt = run.time().deltaTValue();
            const scalar solidDt = run.fsi().solid().timeStep();
            if (!run.step())
            {
                break;
            }
            r.dt.push_back(dt);
            r.solidDt.push_back(solidDt);
            r.substeps.push_back(run.fsi().solid().substeps());
        }
        r.time = run.time().value();
        r.u = run.fsi().solid().displacement();
        r.v = run.fsi().solid().velocity();
        r.fluidWork = run.fsi().wallWork();
        r.solidWork = run.fsi().solid().energy().externalWork;
    }
    r.rows =
        readCouplingLog(tc.dir()/"postProcessing"/"fsi"/"0"/"coupling.dat");
    return r;
}


//- The impulse of the wall force over the run (coupling.dat Fx at the
//  step ends, trapezoidal rule from 0 at t = 0 on the rows' times) [N s]
scalar wallImpulse(const endResult& r)
{
    scalar impulse = 0, t0 = 0, f0 = 0;
    for (const couplingRow& row : r.rows)
    {
        impulse += 0.5*(f0 + row.force.x())*(row.time - t0);
        t0 = row.time;
        f0 = row.force.x();
    }
    return impulse;
}


TEST(fluidSolidInteraction, solidSubcyclesWithinTheCoupledStep)
{
    // Solid elements of 62.5 nm: the solid's stable step (~3.3e-11 s) is
    // a fifth of the fluid's Courant step (maxCo 0.5 on 0.5 um cells,
    // ~1.7e-10 s). Lock step (default solidSubcycles 1) against 4
    // subcycles and, for the order of the difference, 2
    const scalar endTime = 3e-9;
    const endResult r1 = runToEnd(80, 0, endTime);
    const endResult r2 = runToEnd(80, 2, endTime);
    const endResult r4 = runToEnd(80, 4, endTime);

    // The steps: at most N solid steps (also those adjusted to end on the
    // end time), each of m = ceil(dt/solid step) substeps (N at the
    // clamp), or one more where the stable step fell below dt/m within
    // the step (the substeps follow it, as the lock step does)
    const auto checkSteps = [](const endResult& r, const label N)
    {
        label clamped = 0, more = 0;
        for (size_t i = 0; i < r.dt.size(); ++i)
        {
            const label expected =
                label(std::ceil(r.dt[i]/r.solidDt[i]*(1 - 1e-12)));
            std::ostringstream what;
            what<< "N " << N << ", step " << i + 1 << ": dt " << r.dt[i]
                << " s, solid step " << r.solidDt[i] << " s";
            EXPECT_GE(r.substeps[i], expected) << what.str();
            if (r.substeps[i] != expected)
            {
                ++more;
                EXPECT_EQ(r.substeps[i], expected + 1) << what.str();
            }
            EXPECT_LE(r.dt[i], N*r.solidDt[i]*(1 + 1e-12)) << what.str();
            if (r.dt[i] > (N - 0.5)*r.solidDt[i])
            {
                ++clamped;
                EXPECT_GE(r.substeps[i], N) << what.str();
            }
        }
        // The solid's step limits the coupled step most of the run; one
        // substep more in few steps
        EXPECT_GE(clamped, label(r.dt.size()/2))
            << "N " << N << ": " << clamped << " of " << r.dt.size()
            << " steps at the clamp";
        EXPECT_LE(more, label(r.dt.size()/10))
            << "N " << N << ": " << more << " of " << r.dt.size()
            << " steps with a substep more";
        std::printf("N %d: %d steps, %d at the clamp, %d with a substep "
            "more\n", int(N), int(r.dt.size()), int(clamped), int(more));
    };
    checkSteps(r1, 1);
    checkSteps(r2, 2);
    checkSteps(r4, 4);
    const scalar dtMax1 = *std::max_element(r1.dt.begin(), r1.dt.end());
    const scalar dtMax4 = *std::max_element(r4.dt.begin(), r4.dt.end());
    EXPECT_GE(dtMax4, 3.9*dtMax1);
    EXPECT_LE(r4.dt.size(), r1.dt.size()/3);

    // The same end time, the same answer to the time discretisation
    EXPECT_NEAR(r4.time, r1.time, 1e-12*endTime);
    EXPECT_NEAR(r2.time, r1.time, 1e-12*endTime);
    const scalar uMax = r1.u.cwiseAbs().maxCoeff();
    const scalar vMax = r1.v.cwiseAbs().maxCoeff();
    const scalar du2 = (r2.u - r1.u).cwiseAbs().maxCoeff()/uMax;
    const scalar du4 = (r4.u - r1.u).cwiseAbs().maxCoeff()/uMax;
    const scalar dv4 = (r4.v - r1.v).cwiseAbs().maxCoeff()/vMax;
    const scalar I1 = wallImpulse(r1);
    const scalar dI2 = mag(wallImpulse(r2) - I1)/mag(I1);
    const scalar dI4 = mag(wallImpulse(r4) - I1)/mag(I1);
    const auto energy = [](const endResult& r)
    {
        return mag(r.fluidWork - r.solidWork)/mag(r.solidWork);
    };
    std::printf("solidSubcycles 1, 2, 4: largest dt %.4e, %.4e s; against"
        " N 1 at %.6e s: solid displacement %.3e, %.3e [-] of %.4e m,"
        " velocity (N 4) %.3e [-] of %.4e m/s, wall impulse %.3e,"
        " %.3e [-] of %.4e N s; interface work fluid/solid %.6e/%.6e, %.6e/%.6e,"
        " %.6e/%.6e J, relative %.3e, %.3e, %.3e\n", dtMax1, dtMax4,
        r1.time, du2, du4, uMax, dv4, vMax, dI2, dI4, I1, r1.fluidWork,
        r1.solidWork, r2.fluidWork, r2.solidWork, r4.fluidWork,
        r4.solidWork, energy(r1), energy(r2), energy(r4));

    // Against lock step: the time discretisation error at 2 and 4 times
    // its step. Measured (2026-12-03): displacement 1.66e-3 and 6.56e-3,
    // impulse 1.69e-3 and 6.68e-3, velocity (N 4, the shock front in the
    // solid) 1.9e-2; the ratio 3.96 = (4^p - 1)/(2^p - 1) gives an
    // observed order p = 1.6 (second order in the smooth load, first at
    // the shock fronts). Tolerances 1.5 times the measured; the load held
    // at f_n+1 over the substeps (not linear from f_n) gives 3.3e-3 and
    // 1.6e-2 in the displacement
    EXPECT_LE(du2, 2.5e-3);
    EXPECT_LE(du4, 1e-2);
    EXPECT_LE(dI2, 2.5e-3);
    EXPECT_LE(dI4, 1e-2);
    EXPECT_LE(dv4, 3e-2);

    // The interface energy balance closes to first order in dt: the
    // fluid's wall increments dt x and the solid's differ by O(dt^2) per
    // step. Measured 1.1e-3, 3.1e-4, 5.2e-3 for N 1, 2, 4; tolerance
    // 2e-3 N. The load held at f_n+1: 3.3e-3 (N 2), 2.4e-2 (N 4)
    EXPECT_LE(energy(r1), 2e-3);
    EXPECT_LE(energy(r2), 4e-3);
    EXPECT_LE(energy(r4), 8e-3);
}


//- A restart from the write time of step 2 of 4 continues bitwise (the
//  case of writeCase with these solid cells and subcycles)
void checkRestartBitwise(const label solidCells, const label solidSubcycles)
{
    const label nSteps = 4;

    // Uninterrupted: nSteps steps
    foamUnit::testCase whole("fluidSolidInteraction");
    writeCase(whole, 5e7, solidCells, solidSubcycles);
    whole.writeFile("system/controlDict", controlDictText("startTime", 2));
    fsiRun a(whole.dir());
    for (label n = 0; n < nSteps; ++n)
    {
        ASSERT_TRUE(a.step());
    }
    a.finish();

    // Stopped after the write of step 2, restarted from latestTime
    foamUnit::testCase parts("fluidSolidInteraction");
    writeCase(parts, 5e7, solidCells, solidSubcycles);
    parts.writeFile("system/controlDict", controlDictText("startTime", 2));
    {
        fsiRun first(parts.dir());
        ASSERT_TRUE(first.step());
        ASSERT_TRUE(first.step());
        first.finish();
    }
    parts.writeFile("system/controlDict", controlDictText("latestTime", 2));
    fsiRun b(parts.dir());
    ASSERT_GT(b.time().value(), 0);
    for (label n = 2; n < nSteps; ++n)
    {
        ASSERT_TRUE(b.step());
        if (solidSubcycles > 1)
        {
            EXPECT_GT(b.fsi().solid().substeps(), 1) << "step " << n + 1;
        }
    }
    b.finish();

    EXPECT_EQ(b.time().timeIndex(), a.time().timeIndex());
    EXPECT_EQ(b.time().value(), a.time().value());
    EXPECT_EQ(b.time().deltaTValue(), a.time().deltaTValue());
    EXPECT_EQ(firstDifference(b.mesh().points(), a.mesh().points()), -1);
    EXPECT_EQ
    (
        firstDifference
        (
            b.fluid().rho().primitiveField(),
            a.fluid().rho().primitiveField()
        ),
        -1
    );
    EXPECT_EQ
    (
        firstDifference
        (
            b.fluid().rhoU().primitiveField(),
            a.fluid().rhoU().primitiveField()
        ),
        -1
    );
    EXPECT_EQ
    (
        firstDifference
        (
            b.fluid().rhoE().primitiveField(),
            a.fluid().rhoE().primitiveField()
        ),
        -1
    );
    const solidDomain& sa = a.fsi().solid();
    const solidDomain& sb = b.fsi().solid();
    EXPECT_EQ(firstDifference(sb.displacement(), sa.displacement()), -1);
    EXPECT_EQ(firstDifference(sb.velocity(), sa.velocity()), -1);
    EXPECT_EQ(firstDifference(sb.acceleration(), sa.acceleration()), -1);

    // The restarted coupling.dat (postProcessing/fsi/<restart time>) holds
    // the rows of steps 3 and 4 of the uninterrupted run
    const std::vector<couplingRow> rowsA =
        readCouplingLog(whole.dir()/"postProcessing"/"fsi"/"0"/"coupling.dat");
    const fileNameList restartLogs
    (
        readDir(parts.dir()/"postProcessing"/"fsi", fileName::DIRECTORY)
    );
    ASSERT_EQ(restartLogs.size(), 2);
    const word restartName =
        restartLogs[0] == "0" ? restartLogs[1] : restartLogs[0];
    const std::vector<couplingRow> rowsB = readCouplingLog
    (
        parts.dir()/"postProcessing"/"fsi"/restartName/"coupling.dat"
    );
    ASSERT_EQ(rowsA.size(), size_t(nSteps));
    ASSERT_EQ(rowsB.size(), size_t(nSteps - 2));
    for (size_t i = 0; i < rowsB.size(); ++i)
    {
        EXPECT_EQ(rowsB[i].text, rowsA[i + 2].text);
    }
}


TEST(fluidSolidInteraction, restartContinuesBitwise)
{
    checkRestartBitwise(10, 0);
}


TEST(fluidSolidInteraction, restartContinuesBitwiseSubcycled)
{
    // Elements of 31 nm: steps 3 and 4 take two solid substeps each, the
    // load of the step after the restart starting from the interface
    // forces of uniform/solidState
    checkRestartBitwise(160, 4);
}


// ************************************************************************* //
