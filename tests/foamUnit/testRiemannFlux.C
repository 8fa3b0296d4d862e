/*---------------------------------------------------------------------------*\
Description
    Unit tests of the face fluxes of src/riemannFluxes (HLLC, HLL, rusanov)
    on small meshes with the Mie-Grueneisen water of rhoEThermo:

    - consistency: a uniform state gives the exact flux (mass rho U.Sf,
      momentum rho U (U.Sf) + p Sf, energy (rho E + p) U.Sf) on interior
      and boundary faces, on a skewed mesh;
    - conservation: a closed box at rest is in equilibrium cell by cell;
      its walls pass no mass, no energy and no tangential force, whatever
      the state inside;
    - supersonic upwinding (HLLC, HLL: all waves one way): the flux is the
      upwind state's;
    - moving mesh: with the face speeds of mesh.phi() a uniform state
      gets the exact flux in the frame of the faces,
      rho U (U.Sf - phi) + p Sf etc. (it stays uniform);
    - HLLC resolves a contact with shear exactly (equal p and normal u,
      different rho and tangential U): the upwind state's flux.

    The exact fluxes are computed here from (rho, U, p) and e(rho, p) of
    the law, not through the library's own physicalFlux.

\*---------------------------------------------------------------------------*/

#include "riemannFlux.H"
#include "rhoEThermoModel.H"
#include "MieGruneisen.H"
#include "zeroGradientFvPatchFields.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "foamTestCase.H"
#include "goldFile.H"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace Foam;

namespace
{

const foamUnit::goldFile& gold()
{
    static const foamUnit::goldFile g("riemannFlux");
    return g;
}

const wordList solvers{"HLLC", "HLL", "rusanov"};

//- The riemann dictionary of riemannFlux.H's Usage (system/fvSolution)
dictionary riemannDict(const word& solver)
{
    IStringStream is
    (
        foamUnit::testCase::usageExample
        (
            "src/riemannFluxes/riemannFlux/riemannFlux.H"
        )
    );
    dictionary d(dictionary(is).subDict("riemann"));
    d.set("riemannSolver", solver);
    return d;
}

//- Primitive state and its exact flux through Sf
struct state
{
    scalar rho;
    vector U;
    scalar p;
    scalar e;
    scalar c;

    void flux
    (
        const vector& Sf,
        const scalar phi,
        scalar& mass,
        vector& momentum,
        scalar& energy
    ) const
    {
        const scalar vol = (U & Sf) - phi;
        mass = rho*vol;
        momentum = mass*U + p*Sf;
        energy = rho*(e + 0.5*magSqr(U))*vol + p*(U & Sf);
    }
};

//- A mesh with the water of the Usage example of rhoEThermo.H, U
//  (zeroGradient) and the flux fields
struct fluxCase
{
    foamUnit::testCase tc;
    autoPtr<fvMesh> mesh;
    autoPtr<rhoEThermo> thermo;
    autoPtr<volVectorField> U;
    autoPtr<surfaceScalarField> mass;
    autoPtr<surfaceVectorField> momentum;
    autoPtr<surfaceScalarField> energy;
    autoPtr<surfaceScalarField> amaxSf;

    fluxCase
    (
        const Vector<label>& n,
        const std::function<point(const vector&)>& map,
        const word& patchType
    )
    :
        tc("riemannFlux")
    {
        tc.writeThermophysicalProperties("mieGruneisen");
        // Walls and symmetry planes take their outer state by reflection;
        // the field condition there only needs to be valid
        tc.writeUniformField("p", dimPressure, 1e5, "zeroGradient");
        tc.writeUniformField("T", dimTemperature, 300, "zeroGradient");
        mesh = tc.blockMesh
        (
            n, map,
            {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"},
            {patchType, patchType, patchType, patchType, patchType, patchType}
        );
        thermo = rhoEThermo::New(mesh());
        const fvMesh& m = mesh();
        auto io = [&](const word& name)
        {
            return IOobject(name, m.time().timeName(), m);
        };
        U.reset
        (
            new volVectorField
            (
                io("U"), m, dimensionedVector(dimVelocity, Zero),
                zeroGradientFvPatchVectorField::typeName
            )
        );
        mass.reset
        (
            new surfaceScalarField
            (
                io("phi"), m, dimensionedScalar(dimMass/dimTime, Zero)
            )
        );
        momentum.reset
        (
            new surfaceVectorField
            (
                io("phiU"), m, dimensionedVector(dimForce, Zero)
            )
        );
        energy.reset
        (
            new surfaceScalarField
            (
                io("phiE"), m, dimensionedScalar(dimPower, Zero)
            )
        );
        amaxSf.reset
        (
            new surfaceScalarField
            (
                io("amaxSf"), m, dimensionedScalar(dimVolume/dimTime, Zero)
            )
        );
    }

    const eos::MieGruneisen& law() const
    {
        return dynamic_cast<const rhoEThermoModel<eos::MieGruneisen>&>
        (
            thermo()
        ).law();
    }

    //- Make a state complete (e, c) from rho, U, p
    state makeState(const scalar rho, const vector& U, const scalar p) const
    {
        const scalar e = law().e(rho, p);
        return state{rho, U, p, e, std::sqrt(law().c2(rho, e))};
    }

    //- Set the cell states (p exactly as given) and compute the fluxes
    void setAndSolve(const List<state>& s, const word& solver)
    {
        scalarField rho(s.size()), e(s.size()), p(s.size());
        vectorField Uc(s.size());
        forAll(s, i)
        {
            rho[i] = s[i].rho;
            e[i] = s[i].e;
            p[i] = s[i].p;
            Uc[i] = s[i].U;
        }
        thermo->rho().primitiveFieldRef() = rho;
        thermo->e().primitiveFieldRef() = e;
        thermo->correct();
        thermo->p().primitiveFieldRef() = p;
        thermo->p().correctBoundaryConditions();
        U->primitiveFieldRef() = Uc;
        U->correctBoundaryConditions();
        autoPtr<riemannFlux> flux
        (
            riemannFlux::New(mesh(), riemannDict(solver))
        );
        flux->fluxes(thermo(), U(), mass(), momentum(), energy(), amaxSf());
    }

    //- Largest error of the fluxes of face facei (patchi -1: internal)
    //  against the exact flux of s through it, relative to the flux
    //  scales of s
    scalar faceError
    (
        const label patchi,
        const label facei,
        const state& s,
        const scalar phi
    ) const
    {
        const bool internal = patchi < 0;
        const vector Sf = internal
            ? mesh->Sf()[facei] : mesh->Sf().boundaryField()[patchi][facei];
        const scalar A = mag(Sf);
        scalar m;
        vector M;
        scalar E;
        s.flux(Sf, phi, m, M, E);
        const scalar v = s.c + mag(s.U) + mag(phi)/A;
        const scalar mScale = s.rho*v*A;
        const scalar MScale = mScale*v + mag(s.p)*A;
        const scalar EScale = mScale*(mag(s.e) + v*v) + mag(s.p)*v*A;
        auto pick = [&](const auto& f)
        {
            return internal ? f.primitiveField()[facei]
                            : f.boundaryField()[patchi][facei];
        };
        return max
        (
            max(mag(pick(mass()) - m)/mScale, mag(pick(momentum()) - M)/MScale),
            mag(pick(energy()) - E)/EScale
        );
    }
};

//- A skewed, slightly curved box: 3 x 2 x 2 mm
point skewedBox(const vector& s)
{
    return 1e-3*vector
    (
        3*s.x() + 0.4*s.y() + 0.1*std::sin(3*s.z()),
        2*s.y() + 0.3*s.z() + 0.05*s.x()*s.x(),
        2*s.z() + 0.2*s.x()
    );
}

point row(const vector& s)
{
    return 1e-3*vector(4*s.x(), s.y(), s.z());
}

} // End anonymous namespace


TEST(riemannFlux, uniformStateGivesThePhysicalFlux)
{
    fluxCase c({3, 2, 2}, skewedBox, "patch");
    const state s0 = c.makeState(1050, vector(120, -40, 30), 0);
    for (const word& solver : solvers)
    {
        SCOPED_TRACE(solver);
        c.setAndSolve(List<state>(c.mesh->nCells(), s0), solver);
        scalar errInternal = 0, errBoundary = 0;
        forAll(c.mesh->Sf(), facei)
        {
            errInternal = max(errInternal, c.faceError(-1, facei, s0, 0));
        }
        forAll(c.mesh->boundary(), patchi)
        {
            forAll(c.mesh->boundary()[patchi], facei)
            {
                errBoundary =
                    max(errBoundary, c.faceError(patchi, facei, s0, 0));
            }
        }
        gold().check(solver + ".uniform.internalRelError", errInternal);
        gold().check(solver + ".uniform.boundaryRelError", errBoundary);
    }
}


TEST(riemannFlux, closedBoxConservesMassAndEnergy)
{
    fluxCase c({3, 2, 2}, skewedBox, "wall");
    const fvMesh& mesh = c.mesh();
    for (const word& solver : solvers)
    {
        SCOPED_TRACE(solver);

        // At rest, uniform: every cell in equilibrium
        const state rest = c.makeState(1020, Zero, 5e6);
        c.setAndSolve(List<state>(mesh.nCells(), rest), solver);
        const scalarField& m = c.mass->primitiveField();
        const vectorField& M = c.momentum->primitiveField();
        const scalarField& E = c.energy->primitiveField();
        scalarField netM(mesh.nCells(), Zero), netE(mesh.nCells(), Zero);
        vectorField netP(mesh.nCells(), Zero);
        forAll(m, facei)
        {
            const label o = mesh.owner()[facei], n = mesh.neighbour()[facei];
            netM[o] += m[facei]; netM[n] -= m[facei];
            netP[o] += M[facei]; netP[n] -= M[facei];
            netE[o] += E[facei]; netE[n] -= E[facei];
        }
        forAll(mesh.boundary(), patchi)
        {
            const labelUList& fc = mesh.boundary()[patchi].faceCells();
            forAll(fc, facei)
            {
                netM[fc[facei]] += c.mass->boundaryField()[patchi][facei];
                netP[fc[facei]] += c.momentum->boundaryField()[patchi][facei];
                netE[fc[facei]] += c.energy->boundaryField()[patchi][facei];
            }
        }
        const scalar A = gMax(mesh.magSf());
        const scalar mScale = rest.rho*rest.c*A;
        scalar err = max(mag(netM))/mScale;
        err = max(err, max(mag(netP))/(mag(rest.p)*A));
        err = max(err, max(mag(netE))/(mScale*rest.c*rest.c));
        gold().check(solver + ".rest.cellImbalance", err);

        // Any state: the walls pass no mass, no energy, no tangential force
        List<state> s(mesh.nCells());
        forAll(s, celli)
        {
            const scalar x = celli + 1;
            s[celli] = c.makeState
            (
                1000 + 40*std::sin(x),
                vector(50*std::cos(2*x), 30*std::sin(3*x), -20*std::cos(x)),
                1e7*(1 + std::sin(5*x))
            );
        }
        c.setAndSolve(s, solver);
        scalar errWall = 0;
        forAll(mesh.boundary(), patchi)
        {
            const fvPatch& patch = mesh.boundary()[patchi];
            const vectorField n(patch.nf());
            forAll(patch, facei)
            {
                const state& si = s[patch.faceCells()[facei]];
                const scalar a = patch.magSf()[facei];
                const scalar v = si.c + mag(si.U);
                const scalar mScale = si.rho*v*a;
                const vector Mf = c.momentum->boundaryField()[patchi][facei];
                errWall = max
                (
                    errWall,
                    mag(c.mass->boundaryField()[patchi][facei])/mScale
                );
                errWall = max
                (
                    errWall,
                    mag(c.energy->boundaryField()[patchi][facei])
                   /(mScale*(mag(si.e) + v*v) + mag(si.p)*v*a)
                );
                errWall = max
                (
                    errWall,
                    mag(Mf - (Mf & n[facei])*n[facei])/(mScale*v + si.p*a)
                );
            }
        }
        gold().check(solver + ".wall.relFlux", errWall);
    }
}


TEST(riemannFlux, supersonicFlowTakesTheUpwindFlux)
{
    // A row of 4 cells in x, all waves one way (|U.x| > c in every cell):
    // the exact Godunov flux, which HLLC and HLL reproduce
    fluxCase c({4, 1, 1}, row, "patch");
    const fvMesh& mesh = c.mesh();
    for (const word& solver : wordList({"HLLC", "HLL"}))
    {
        for (const scalar ux : {4000, -4000})
        {
            SCOPED_TRACE(solver + std::string(" ux ") + std::to_string(ux));
            const scalar rho[4] = {1000, 1080, 1150, 980};
            const scalar p[4] = {1e5, 2e8, 5e8, -1e7};
            List<state> s(4);
            forAll(s, i)
            {
                s[i] = c.makeState(rho[i], vector(ux, 200, -100*i), p[i]);
                ASSERT_GT(mag(ux), s[i].c);
            }
            c.setAndSolve(s, solver);
            scalar err = 0;
            forAll(mesh.Sf(), facei)
            {
                const bool ownerUpwind = (mesh.Sf()[facei].x()*ux) > 0;
                const label upwind = ownerUpwind
                    ? mesh.owner()[facei] : mesh.neighbour()[facei];
                err = max(err, c.faceError(-1, facei, s[upwind], 0));
            }
            gold().check(word(solver) + ".supersonic.relError", err);
        }
    }
}


TEST(riemannFlux, movingMeshUniformStateFluxInTheFrameOfTheFaces)
{
    fluxCase c({3, 2, 2}, skewedBox, "patch");
    fvMesh& mesh = c.mesh();
    // A new time step (the mesh keeps the old points of the step)
    ++c.tc.time();
    // A smooth non-uniform motion of the points over one time step:
    // face speeds up to about 20 m/s
    const scalar dt = mesh.time().deltaTValue();
    pointField newPoints(mesh.points());
    forAll(newPoints, pointi)
    {
        const point& x = mesh.points()[pointi];
        newPoints[pointi] += 20*dt*vector
        (
            std::sin(2e3*x.y()), std::cos(1.5e3*x.z()), std::sin(1e3*x.x())
        );
    }
    mesh.movePoints(newPoints);
    ASSERT_TRUE(mesh.moving());
    ASSERT_GT(gMax(mag(mesh.phi())().primitiveField()), 0);

    const state s0 = c.makeState(1050, vector(120, -40, 30), 3e7);
    for (const word& solver : solvers)
    {
        SCOPED_TRACE(solver);
        c.setAndSolve(List<state>(mesh.nCells(), s0), solver);
        scalar err = 0;
        forAll(mesh.Sf(), facei)
        {
            err = max(err, c.faceError(-1, facei, s0, mesh.phi()[facei]));
        }
        forAll(mesh.boundary(), patchi)
        {
            forAll(mesh.boundary()[patchi], facei)
            {
                err = max
                (
                    err,
                    c.faceError
                    (
                        patchi, facei, s0,
                        mesh.phi().boundaryField()[patchi][facei]
                    )
                );
            }
        }
        gold().check(solver + ".moving.relError", err);
    }
}


TEST(riemannFlux, HLLCResolvesAContactExactly)
{
    // rho and the tangential velocity jump at x = 2 mm, p and u equal:
    // a contact (with shear) moving with u. HLLC gives the upwind state's
    // flux; HLL smears the contact (its flux differs: the case is a jump)
    fluxCase c({4, 1, 1}, row, "patch");
    const fvMesh& mesh = c.mesh();
    for (const scalar u : {25.0, -25.0, 0.0})
    {
        SCOPED_TRACE(u);
        List<state> s(4);
        forAll(s, i)
        {
            s[i] = i < 2
                ? c.makeState(1000, vector(u, 5, -3), 2e7)
                : c.makeState(1060, vector(u, -7, 2), 2e7);
        }
        scalar errHLLC = 0, errHLL = 0;
        for (const word& solver : wordList({"HLLC", "HLL"}))
        {
            c.setAndSolve(s, solver);
            scalar err = 0;
            forAll(mesh.Sf(), facei)
            {
                const label upwind = u >= 0
                    ? mesh.owner()[facei] : mesh.neighbour()[facei];
                err = max(err, c.faceError(-1, facei, s[upwind], 0));
            }
            (solver == "HLLC" ? errHLLC : errHLL) = err;
        }
        gold().check("HLLC.contact.relError", errHLLC);
        EXPECT_GT(errHLL, 1e-4) << "HLL resolved the contact: not a contact?";
    }
}


TEST(riemannFlux, unknownSolverListsTheValidOnes)
{
    fluxCase c({2, 1, 1}, row, "patch");
    try
    {
        riemannFlux::New(c.mesh(), riemannDict("Roe"));
        ADD_FAILURE() << "accepted";
    }
    catch (const Foam::IOerror& err)
    {
        for (const std::string m : {"Roe", "HLLC", "HLL", "rusanov"})
        {
            EXPECT_NE(err.message().find(m), std::string::npos)
                << "no '" << m << "' in: " << err.message();
        }
    }
}
