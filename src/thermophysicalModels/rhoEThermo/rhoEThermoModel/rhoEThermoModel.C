#include "rhoEThermoModel.H"
#include "eosStatus.H"
#include "isentropeTable.H"
#include "keywordCheck.H"

#include <cstdint>
#include <cstring>
#include <limits>

namespace
{

//- x is neither NaN nor infinite, from its bits: no floating-point
//  operation, so no trap with FOAM_SIGFPE (GCC 12's std::isfinite of a NaN
//  raises FE_INVALID: GCC bug 66462; the NaN density of a pressure outside
//  the law trapped inside the checks, issue 19)
inline bool finiteBits(const double x)
{
    std::uint64_t u;
    std::memcpy(&u, &x, sizeof u);
    return (u & 0x7ff0000000000000ULL) != 0x7ff0000000000000ULL;
}

} // End anonymous namespace

template<class Law>
Law Foam::rhoEThermoModel<Law>::makeLaw(const dictionary& dict)
{
    const dictionary& coeffs =
        dict.subDict(word(Law::typeName) + "Coeffs");
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
        // finiteness first: a comparison with a NaN traps under sigFpe
        const scalar c2 =
            finiteBits(rho[i]) && finiteBits(e[i]) ? law_.c2(rho[i], e[i]) : 0;
        c[i] = finiteBits(c2) && c2 > 0 ? std::sqrt(c2) : 0;
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
        if (finiteBits(p[i]) && finiteBits(T[i]))
        {
            rho[i] = law_.rhoFromPT(p[i], T[i]);
            e[i] = finiteBits(rho[i]) ? law_.eFromT(rho[i], T[i]) : rho[i];
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
            !finiteBits(rho[i]) ? eos::Status::nonPositiveDensity
          : !finiteBits(e[i]) ? eos::Status::nonFiniteEnergy
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
        finiteBits(rho) && finiteBits(e)
     && law_.check(rho, e) == eos::Status::ok;
}


template<class Law>
Foam::string Foam::rhoEThermoModel<Law>::reasonPT
(
    const scalar p,
    const scalar T
) const
{
    // eos::checkPT's steps, each value's finiteness from its bits
    eos::Status s = eos::Status::ok;
    if (!finiteBits(p) || !finiteBits(T))
    {
        s = eos::Status::nonFinitePT;
    }
    else if (!(T > 0))
    {
        s = eos::Status::nonPositiveTemperature;
    }
    else
    {
        const scalar rho = law_.rhoFromPT(p, T);
        const scalar e = finiteBits(rho) ? law_.eFromT(rho, T) : rho;
        s =
            !finiteBits(rho) ? eos::Status::noDensityForPT
          : !finiteBits(e) ? eos::Status::nonFiniteEnergy
          : law_.check(rho, e);
    }
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
