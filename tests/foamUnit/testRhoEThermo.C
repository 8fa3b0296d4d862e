/*---------------------------------------------------------------------------*\
Description
    Unit tests of rhoEThermo (src/thermophysicalModels/rhoEThermo) on a
    small mesh: the fields p, c, T of every law equal the plain C++ core
    (src/eos) built from the same coefficients; c^2 is the derivative of p
    along the isentrope de = p/rho^2 drho; T, e, rho round trips; the
    Mie-Grueneisen law reproduces its Hugoniot (Rankine-Hugoniot states
    from Us = C0 + s Up); invalid states and bad coefficients give errors
    naming the cell or the entry.

    The dictionary is the Usage example of rhoEThermo.H (all three laws'
    coefficients), with equationOfState set per test: the documented
    example must stay a valid input.

\*---------------------------------------------------------------------------*/

#include "rhoEThermoModel.H"
#include "MieGruneisen.H"
#include "StiffenedGas.H"
#include "IdealGas.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "foamTestCase.H"
#include "goldFile.H"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>

#include <cmath>
#include <string>
#include <vector>

using namespace Foam;

namespace
{

const foamUnit::goldFile& gold()
{
    static const foamUnit::goldFile g("rhoEThermo");
    return g;
}

//- The Usage example of rhoEThermo.H
dictionary usageDict()
{
    IStringStream is
    (
        foamUnit::testCase::usageExample
        (
            "src/thermophysicalModels/rhoEThermo/rhoEThermo/rhoEThermo.H"
        )
    );
    return dictionary(is);
}

std::string fileText(const dictionary& dict)
{
    OStringStream os;
    os.precision(17);
    os  << "FoamFile { version 2.0; format ascii; class dictionary;"
        << " object thermophysicalProperties; }" << nl;
    dict.write(os, false);
    return os.str();
}

//- Plain core of a law from the coefficients as a user reads them
eos::MieGruneisen makeCore(const dictionary& d, const eos::MieGruneisen*)
{
    eos::MieGruneisen::Parameters par;
    par.rho0 = d.get<scalar>("rho0");
    par.C0 = d.get<scalar>("C0");
    par.s = d.get<scalar>("s");
    par.Gamma0 = d.get<scalar>("Gamma0");
    par.Cv = d.get<scalar>("Cv");
    par.T0 = d.get<scalar>("T0");
    return eos::MieGruneisen(par);
}

eos::StiffenedGas makeCore(const dictionary& d, const eos::StiffenedGas*)
{
    eos::StiffenedGas::Parameters par;
    par.gamma = d.get<scalar>("gamma");
    par.pInf = d.get<scalar>("pInf");
    par.Cv = d.get<scalar>("Cv");
    return eos::StiffenedGas(par);
}

eos::IdealGas makeCore(const dictionary& d, const eos::IdealGas*)
{
    eos::IdealGas::Parameters par;
    par.gamma = d.get<scalar>("gamma");
    par.Cv = d.get<scalar>("Cv");
    return eos::IdealGas(par);
}

//- A case with one cell per state (a row of hexahedra, zeroGradient p
//  and T) and the thermo of one law
struct thermoCase
{
    foamUnit::testCase tc;
    autoPtr<fvMesh> mesh;
    autoPtr<rhoEThermo> thermo;

    thermoCase
    (
        const word& law,
        const label nCells,
        const dictionary& dict,
        const word& pPatchType = "zeroGradient"
    )
    :
        tc("rhoEThermo-" + law)
    {
        dictionary d(dict);
        d.set("equationOfState", law);
        tc.writeFile("constant/thermophysicalProperties", fileText(d));
        tc.writeUniformField("p", dimPressure, 1e5, pPatchType);
        tc.writeUniformField("T", dimTemperature, 300, "zeroGradient");
        const word side("patch");
        mesh = tc.blockMesh
        (
            {nCells, 1, 1},
            [&](const vector& s)
            {
                return 1e-3*cmptMultiply(s, vector(nCells, 1, 1));
            },
            {"sides", "sides", "sides", "sides", "sides", "sides"},
            {side, side, side, side, side, side}
        );
        thermo = rhoEThermo::New(mesh());
    }

    void setStates(const scalarField& rho, const scalarField& e)
    {
        thermo->rho().primitiveFieldRef() = rho;
        thermo->e().primitiveFieldRef() = e;
        thermo->correct();
    }
};

//- Valid states of a law on a grid of densities and energies
template<class Law>
void validStates
(
    const Law& core,
    const std::vector<scalar>& rhos,
    const std::vector<scalar>& es,
    scalarField& rho,
    scalarField& e
)
{
    DynamicList<scalar> r, en;
    for (const scalar ri : rhos)
    {
        for (const scalar ei : es)
        {
            if (core.check(ri, ei) == eos::Status::ok)
            {
                r.append(ri);
                en.append(ei);
            }
        }
    }
    rho.transfer(r);
    e.transfer(en);
}

template<class Law>
void checkLaw
(
    const std::vector<scalar>& rhos,
    const std::vector<scalar>& es
)
{
    const word law(Law::typeName);
    SCOPED_TRACE(law);
    const dictionary dict(usageDict());
    const Law core
    (
        makeCore(dict.subDict(law + "Coeffs"), static_cast<const Law*>(nullptr))
    );
    scalarField rho, e;
    validStates(core, rhos, es, rho, e);
    ASSERT_GE(rho.size(), 6) << "too few valid states of the law";

    thermoCase c(law, rho.size(), dict);
    ASSERT_EQ(c.thermo->lawName(), law);
    c.setStates(rho, e);
    const rhoEThermo& thermo = c.thermo();

    // Fields against the core
    scalar errP = 0, errC = 0, errT = 0;
    forAll(rho, i)
    {
        const scalar p = core.p(rho[i], e[i]);
        const scalar cc = std::sqrt(core.c2(rho[i], e[i]));
        const scalar T = core.T(rho[i], e[i]);
        errP = max(errP, mag(thermo.p()[i] - p)/max(mag(p), rho[i]*cc*cc));
        errC = max(errC, mag(thermo.c()[i] - cc)/cc);
        errT = max(errT, mag(thermo.T()[i] - T)/T);
    }
    gold().check(law + ".maxRelErrorP", errP);
    gold().check(law + ".maxRelErrorC", errC);
    gold().check(law + ".maxRelErrorT", errT);

    // c^2 against the derivative of p along the isentrope through each
    // state: de/drho = p/rho^2 integrated by RK4 to rho (1 +- d)
    // (relative step 1e-6: the Mie-Grueneisen states reach 1 - s eta = 0.06,
    // near the Hugoniot singularity, where 1e-4 leaves 6e-6 of truncation)
    const scalar d = 1e-6;
    auto pOf = [&](const scalar r, const scalar en)
    {
        scalarField p(1);
        thermo.pFromRhoE(scalarField(1, r), scalarField(1, en), p);
        return p[0];
    };
    auto isentrope = [&](scalar r, scalar en, const scalar r1)
    {
        const label n = 8;
        const scalar h = (r1 - r)/n;
        auto f = [&](const scalar x, const scalar y)
        {
            return pOf(x, y)/(x*x);
        };
        for (label k = 0; k < n; ++k)
        {
            const scalar k1 = f(r, en);
            const scalar k2 = f(r + h/2, en + h/2*k1);
            const scalar k3 = f(r + h/2, en + h/2*k2);
            const scalar k4 = f(r + h, en + h*k3);
            en += h/6*(k1 + 2*k2 + 2*k3 + k4);
            r += h;
        }
        return en;
    };
    scalar errIsentrope = 0, errDerivatives = 0;
    forAll(rho, i)
    {
        const scalar r = rho[i], en = e[i], h = d*r;
        const scalar c2 = sqr(thermo.c()[i]);
        const scalar c2s =
            (pOf(r + h, isentrope(r, en, r + h))
           - pOf(r - h, isentrope(r, en, r - h)))/(2*h);
        const scalar he = d*max(mag(en), c2);
        const scalar dpdrho = (pOf(r + h, en) - pOf(r - h, en))/(2*h);
        const scalar dpde = (pOf(r, en + he) - pOf(r, en - he))/(2*he);
        const scalar c2d = dpdrho + pOf(r, en)/(r*r)*dpde;
        errIsentrope = max(errIsentrope, mag(c2s - c2)/c2);
        errDerivatives = max(errDerivatives, mag(c2d - c2)/c2);
    }
    gold().check(law + ".maxRelErrorC2Isentrope", errIsentrope);
    gold().check(law + ".maxRelErrorC2Derivatives", errDerivatives);

    // (rho, e) -> (p, T) -> (rho, e) -> (p, T)
    const scalarField p0(thermo.p().primitiveField());
    const scalarField T0(thermo.T().primitiveField());
    c.thermo->correctFromPT();
    scalarField eT(rho.size());
    forAll(eT, i) eT[i] = core.eFromT(thermo.rho()[i], T0[i]);
    c.thermo->correct();
    scalar errRoundP = 0, errRoundT = 0, errRoundRho = 0, errEFromT = 0;
    forAll(rho, i)
    {
        const scalar scale = rho[i]*sqr(thermo.c()[i]);
        errRoundP = max(errRoundP, mag(thermo.p()[i] - p0[i])/scale);
        errRoundT = max(errRoundT, mag(thermo.T()[i] - T0[i])/T0[i]);
        errRoundRho = max(errRoundRho, mag(thermo.rho()[i] - rho[i])/rho[i]);
        errEFromT = max(errEFromT, mag(thermo.e()[i] - eT[i])/scale*rho[i]);
    }
    gold().check(law + ".roundTripRelErrorP", errRoundP);
    gold().check(law + ".roundTripRelErrorT", errRoundT);
    gold().check(law + ".roundTripRelErrorRho", errRoundRho);
    gold().check(law + ".relErrorEFromT", errEFromT);

    // Boundary states (zeroGradient p, T): those of the adjacent cells
    scalar errBoundary = 0;
    forAll(c.mesh->boundary(), patchi)
    {
        const scalarField cb(thermo.c().boundaryField()[patchi]);
        const scalarField ci
        (
            thermo.c().boundaryField()[patchi].patchInternalField()
        );
        const scalarField rb(thermo.rho().boundaryField()[patchi]);
        const scalarField ri
        (
            thermo.rho().boundaryField()[patchi].patchInternalField()
        );
        forAll(cb, facei)
        {
            errBoundary =
                max(errBoundary, mag(cb[facei] - ci[facei])/ci[facei]);
            errBoundary =
                max(errBoundary, mag(rb[facei] - ri[facei])/ri[facei]);
        }
    }
    gold().check(law + ".boundaryRelError", errBoundary);
}

//- The text of a FatalError/FatalIOError thrown by f, or "" (and a test
//  failure) if none is thrown
template<class F>
std::string errorOf(const F& f)
{
    try
    {
        f();
    }
    catch (const Foam::error& err)
    {
        return err.message();
    }
    ADD_FAILURE() << "no error";
    return std::string();
}

} // End anonymous namespace


TEST(rhoEThermo, mieGruneisenFieldsAgainstTheCore)
{
    // Tension to the strong shock range; e from cooled to hot
    checkLaw<eos::MieGruneisen>
    (
        {800, 900, 950, 1000, 1050, 1100, 1300, 1600, 1900},
        {-2e4, 0, 1e5, 1e6}
    );
}


TEST(rhoEThermo, stiffenedGasFieldsAgainstTheCore)
{
    checkLaw<eos::StiffenedGas>({900, 1000, 1100, 1500}, {7e5, 1e6, 3e6});
}


TEST(rhoEThermo, idealGasFieldsAgainstTheCore)
{
    checkLaw<eos::IdealGas>({0.1, 1, 10, 100}, {1e4, 2.5e5, 1e6});
}


TEST(rhoEThermo, mieGruneisenHugoniot)
{
    // Rankine-Hugoniot from rest (rho0, e = 0, p = 0): behind a shock of
    // particle velocity up, rho = rho0 Us/(Us - up), e = up^2/2 and
    // p = rho0 Us up with Us = C0 + s up (the law's reference curve)
    const dictionary dict(usageDict());
    const dictionary& coeffs = dict.subDict("mieGruneisenCoeffs");
    const scalar rho0 = coeffs.get<scalar>("rho0");
    const scalar C0 = coeffs.get<scalar>("C0");
    const scalar s = coeffs.get<scalar>("s");
    const std::vector<scalar> up{10, 100, 500, 1000, 2000};
    scalarField rho(up.size()), e(up.size()), p(up.size());
    forAll(rho, i)
    {
        const scalar Us = C0 + s*up[i];
        rho[i] = rho0*Us/(Us - up[i]);
        e[i] = 0.5*sqr(up[i]);
        p[i] = rho0*Us*up[i];
    }
    thermoCase c("mieGruneisen", rho.size(), dict);
    c.setStates(rho, e);
    scalar err = 0;
    forAll(p, i) err = max(err, mag(c.thermo->p()[i] - p[i])/p[i]);
    gold().check("mieGruneisen.hugoniotRelErrorP", err);

    // A reference state computed by hand (Python, the header's formulas)
    const scalarField r1(scalarList({1100, 1100, 950}));
    const scalarField e1(scalarList({0, 1e5, 0}));
    thermoCase c1("mieGruneisen", r1.size(), dict);
    c1.setStates(r1, e1);
    gold().check("mieGruneisen.p.rho1100.e0", c1.thermo->p()[0]);
    gold().check("mieGruneisen.p.rho1100.e1e5", c1.thermo->p()[1]);
    gold().check("mieGruneisen.p.rho950.e0", c1.thermo->p()[2]);
    gold().check("mieGruneisen.c.rho1100.e1e5", c1.thermo->c()[1]);
}


TEST(rhoEThermo, ecFromRhoPIsEFromRhoPThenCFromRhoEBitwise)
{
    // The face states' e and c in one pass (issue 18 item 5d, perf45):
    // eFromRhoP, then cFromRhoE of its e, bit for bit, on states inside
    // and outside each law's domain (tension, past the Hugoniot limit, a
    // negative density, NaN: c = 0 there)
    const scalar nan = std::numeric_limits<scalar>::quiet_NaN();
    const scalarField rho
    (
        scalarList
        ({
            1000, 1100, 950, 1600, 1.2, 0.5, 1e-3, -500, 1900, 3000, nan,
            1000, 998.2071, 1012.5
        })
    );
    const scalarField p
    (
        scalarList
        ({
            1e5, 2e8, -3e7, 5e9, 1e5, 2e3, 1, 1e5, 1e10, 1e5, 1e5, nan,
            101325, 6.1e7
        })
    );
    const dictionary dict(usageDict());
    for (const word law : {"mieGruneisen", "stiffenedGas", "idealGas"})
    {
        SCOPED_TRACE(law);
        thermoCase c(law, 2, dict);
        const label n = rho.size();
        scalarField e1(n), c1(n), e2(n), c2(n);
        c.thermo->eFromRhoP(rho, p, e1);
        c.thermo->cFromRhoE(rho, e1, c1);
        c.thermo->ecFromRhoP(rho, p, e2, c2);
        label nPositive = 0, nZero = 0;
        for (label i = 0; i < n; ++i)
        {
            EXPECT_EQ(std::memcmp(&e1[i], &e2[i], sizeof(scalar)), 0)
                << "e of rho = " << rho[i] << ", p = " << p[i];
            EXPECT_EQ(std::memcmp(&c1[i], &c2[i], sizeof(scalar)), 0)
                << "c of rho = " << rho[i] << ", p = " << p[i];
            nPositive += c1[i] > 0 ? 1 : 0;
            nZero += c1[i] == 0 ? 1 : 0;
        }
        EXPECT_GT(nPositive, 3);
        EXPECT_GT(nZero, 0);
    }
}


TEST(rhoEThermo, invalidBoundaryStateNamesTheFirstFace)
{
    // A fixed p on the boundary: faces 1 and 4 at their cells' p (their
    // states copied from the cells'), faces 3 and 5 in tension beyond the
    // law (evaluated on their own, no state): the error names face 3, the
    // first invalid face in face order; with face 3 valid again, face 5
    const dictionary dict(usageDict());
    thermoCase c("mieGruneisen", 8, dict, "fixedValue");
    c.setStates(scalarField(8, 1000), scalarField(8, 1e3));
    volScalarField& p = c.thermo->p();
    const label patchi = 0;
    const labelUList& faceCells = c.mesh->boundary()[patchi].faceCells();
    scalarField pb(p.boundaryField()[patchi]);
    ASSERT_GT(pb.size(), 6);
    pb[1] = p[faceCells[1]];
    pb[4] = p[faceCells[4]];
    pb[3] = -1e11;
    pb[5] = -1e11;
    p.boundaryFieldRef()[patchi] == pb;
    const std::string msg(errorOf([&]{ c.thermo->correct(); }));
    for (const std::string part : {"on patch 'sides'", "face 3 at"})
    {
        EXPECT_NE(msg.find(part), std::string::npos)
            << "no '" << part << "' in: " << msg;
    }
    pb[3] = 1e5;
    p.boundaryFieldRef()[patchi] == pb;
    const std::string msg5(errorOf([&]{ c.thermo->correct(); }));
    EXPECT_NE(msg5.find("face 5 at"), std::string::npos) << msg5;
    pb[5] = 1e5;
    p.boundaryFieldRef()[patchi] == pb;
    EXPECT_NO_THROW(c.thermo->correct());
}


TEST(rhoEThermo, checkStatesNamesTheInvalidCell)
{
    const dictionary dict(usageDict());
    thermoCase c("mieGruneisen", 8, dict);
    scalarField rho(8, 1000), e(8, Zero);
    c.setStates(rho, e);
    EXPECT_NO_THROW(c.thermo->checkStates());

    struct badState
    {
        label cell;
        scalar rho;
        scalar e;
        std::string reason;
    };
    const scalar rhoMax = 1000/(1 - 1/1.99);
    for
    (
        const badState& b :
        {
            badState{3, -1, 0, "density is not positive"},
            badState{5, 1.0001*rhoMax, 0, "Hugoniot"},
            badState{0, 1000, std::nan(""), "not finite"},
            badState{7, 500, 0, "c^2 <= 0"}
        }
    )
    {
        SCOPED_TRACE(b.reason);
        scalarField r(rho), en(e);
        r[b.cell] = b.rho;
        en[b.cell] = b.e;
        c.thermo->rho().primitiveFieldRef() = r;
        c.thermo->e().primitiveFieldRef() = en;
        const std::string msg
        (
            errorOf([&]{ c.thermo->checkStates("hint of the solver"); })
        );
        const std::vector<std::string> parts
        {
            "mieGruneisen", b.reason, "cell " + std::to_string(b.cell) + " at",
            "hint of the solver"
        };
        for (const std::string& part : parts)
        {
            EXPECT_NE(msg.find(part), std::string::npos)
                << "no '" << part << "' in: " << msg;
        }
    }
}


TEST(rhoEThermo, badCoefficientsNameTheEntry)
{
    struct badCase
    {
        std::string law;
        std::string entry;
        std::string value;
        std::vector<std::string> message;
    };
    const std::vector<badCase> cases
    {
        {"mieGruneisen", "C0", "-1450", {"C0", "outside the valid range"}},
        {"mieGruneisen", "Gamma0", "5", {"Gamma0", "must be below 2 s"}},
        // a second token after the value (adv32 s02: 1450 was taken)
        {"mieGruneisen", "C0", "1450 1500", {"C0", "token(s) after its value"}},
        {"mieGruneisen", "C0", "[0 2 -1 0 0 0 0] 1450", {"C0 has dimensions"}},
        {"stiffenedGas", "pInf", "[1 -1 -2 0 0 0 0] -1e9", {"pInf"}},
        {"idealGas", "gamma", "1", {"gamma", "outside the valid range"}},
        {"vanDerWaals", "", "", {"vanDerWaals", "mieGruneisen", "idealGas"}}
    };
    for (const badCase& b : cases)
    {
        SCOPED_TRACE(b.law + " " + b.entry + " " + b.value);
        dictionary dict(usageDict());
        if (!b.entry.empty())
        {
            dictionary& coeffs = dict.subDict(b.law + "Coeffs");
            coeffs.remove(b.entry);
            IStringStream is(b.entry + " " + b.value + ";");
            coeffs.merge(dictionary(is));
        }
        dict.set("equationOfState", word(b.law));
        foamUnit::testCase tc("rhoEThermoBad");
        tc.writeFile("constant/thermophysicalProperties", fileText(dict));
        tc.writeUniformField("p", dimPressure, 1e5, "zeroGradient");
        tc.writeUniformField("T", dimTemperature, 300, "zeroGradient");
        const word side("patch");
        autoPtr<fvMesh> mesh = tc.blockMesh
        (
            {2, 1, 1},
            [](const vector& s) { return 1e-3*s; },
            {"sides", "sides", "sides", "sides", "sides", "sides"},
            {side, side, side, side, side, side}
        );
        try
        {
            rhoEThermo::New(mesh());
            ADD_FAILURE() << "accepted";
        }
        catch (const Foam::IOerror& err)
        {
            EXPECT_NE
            (
                err.ioFileName().find("thermophysicalProperties"),
                std::string::npos
            ) << err.ioFileName();
            for (const std::string& m : b.message)
            {
                EXPECT_NE(err.message().find(m), std::string::npos)
                    << "no '" << m << "' in: " << err.message();
            }
        }
    }
}
