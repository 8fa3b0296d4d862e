#include "rhoEThermoModel.H"
#include "eosStatus.H"
#include "isentropeTable.H"
#include "keywordCheck.H"
#include "subDict.H"

#include <limits>

template<class Law>
Law Foam::rhoEThermoModel<Law>::makeLaw(const dictionary& dict)
{
    const dictionary& coeffs =
        foamTools::subDict(dict, word(Law::typeName) + "Coeffs");
    foamTools::checkKeywords(coeffs, coeffNames());
    try
    {
        return Law(readParameters(coeffs));
    }
    catch (const eos::ParameterError& err)
    {
        FatalIOErrorInFunction(coeffs)
            << err.what() << exit(FatalIOError);
    }
    return Law(typename Law::Parameters());
}


template<class Law>
Foam::rhoEThermoModel<Law>::rhoEThermoModel(const fvMesh& mesh)
:
    rhoEThermo(mesh),
    law_(makeLaw(*this))
{
    correctFromPT();
}


template<class Law>
void Foam::rhoEThermoModel<Law>::pFromRhoE
(
    const scalarField& rho,
    const scalarField& e,
    scalarField& p
) const
{
    forAll(rho, i)
    {
        p[i] = law_.p(rho[i], e[i]);
    }
}


template<class Law>
void Foam::rhoEThermoModel<Law>::eFromRhoP
(
    const scalarField& rho,
    const scalarField& p,
    scalarField& e
) const
{
    forAll(rho, i)
    {
        e[i] = law_.e(rho[i], p[i]);
    }
}


template<class Law>
void Foam::rhoEThermoModel<Law>::cFromRhoE
(
    const scalarField& rho,
    const scalarField& e,
    scalarField& c
) const
{
    forAll(rho, i)
    {
        c[i] = soundSpeed(rho[i], e[i]);
    }
}


template<class Law>
void Foam::rhoEThermoModel<Law>::ecFromRhoP
(
    const scalarField& rho,
    const scalarField& p,
    scalarField& e,
    scalarField& c
) const
{
    // eFromRhoP's and cFromRhoE's expressions per point, the results
    // stored after both (so the law's common terms of the two, e.g. the
    // Mie-Grueneisen cold pressure, are computed once, and no store comes
    // between them: a store to e could be the law's coefficients as far as
    // the compiler knows, which it would then read again; 1.25x the
    // instructions with e stored first)
    forAll(rho, i)
    {
        const scalar r = rho[i];
        const scalar ei = law_.e(r, p[i]);
        const scalar ci = soundSpeed(r, ei);
        e[i] = ei;
        c[i] = ci;
    }
}


template<class Law>
void Foam::rhoEThermoModel<Law>::TFromRhoE
(
    const scalarField& rho,
    const scalarField& e,
    scalarField& T
) const
{
    forAll(rho, i)
    {
        T[i] = law_.T(rho[i], e[i]);
    }
}


template<class Law>
void Foam::rhoEThermoModel<Law>::rhoEFromPT
(
    const scalarField& p,
    const scalarField& T,
    scalarField& rho,
    scalarField& e
) const
{
    forAll(p, i)
    {
        if (eos::isFinite(p[i]) && eos::isFinite(T[i]))
        {
            rho[i] = law_.rhoFromPT(p[i], T[i]);
            e[i] = eos::isFinite(rho[i]) ? law_.eFromT(rho[i], T[i]) : rho[i];
        }
        else
        {
            rho[i] = e[i] = std::numeric_limits<scalar>::quiet_NaN();
        }
    }
}


template<class Law>
Foam::label Foam::rhoEThermoModel<Law>::firstInvalid
(
    const scalarField& rho,
    const scalarField& e,
    string& reason
) const
{
    forAll(rho, i)
    {
        const eos::Status s =
            !eos::isFinite(rho[i]) ? eos::Status::nonPositiveDensity
          : !eos::isFinite(e[i]) ? eos::Status::nonFiniteEnergy
          : law_.check(rho[i], e[i]);
        if (s != eos::Status::ok)
        {
            reason = eos::statusMessage(s);
            return i;
        }
    }
    return -1;
}


template<class Law>
bool Foam::rhoEThermoModel<Law>::valid(const scalar rho, const scalar e) const
{
    return
        eos::isFinite(rho) && eos::isFinite(e)
     && law_.check(rho, e) == eos::Status::ok;
}


template<class Law>
Foam::string Foam::rhoEThermoModel<Law>::reasonPT
(
    const scalar p,
    const scalar T
) const
{
    // eos::checkPT: p and T before any arithmetic, finiteness from bits
    const eos::Status s = eos::checkPT(law_, p, T);
    return eos::statusMessage(s);
}


template<class Law>
riemann::isentropeTable Foam::rhoEThermoModel<Law>::isentrope
(
    const scalar rho,
    const scalar e,
    const scalar pLow,
    const scalar pHigh
) const
{
    return riemann::isentropeTable::build(law_, rho, e, pLow, pHigh);
}
