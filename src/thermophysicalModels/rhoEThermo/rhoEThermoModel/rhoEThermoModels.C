/*---------------------------------------------------------------------------*\
Description
    The laws available to rhoEThermo, each registered under its typeName
    (the value of equationOfState), with its coefficient reader.
\*---------------------------------------------------------------------------*/

#include "rhoEThermoModel.H"
#include "addToRunTimeSelectionTable.H"
#include "MieGruneisen.H"
#include "StiffenedGas.H"
#include "IdealGas.H"
#include "inputChecks.H"
#include "DynamicList.H"
#include "Pair.H"

namespace Foam
{

namespace
{
    //- The coefficients read by readCoeff that are not numbers (name,
    //  text), cleared by checkNumbers
    DynamicList<Pair<word>>& notNumbers()
    {
        static DynamicList<Pair<word>> list;
        return list;
    }

    //- A FatalIOError on dict naming the first coefficient read that is
    //  not a number and the valid range the law gives it (its check of a
    //  value outside every range in its place: eos::validRangeOf)
    template<class Law>
    void checkNumbers
    (
        const dictionary& dict,
        const typename Law::Parameters& par
    )
    {
        if (notNumbers().empty())
        {
            return;
        }
        const Pair<word> first(notNumbers().first());
        notNumbers().clear();
        std::string range;
        try
        {
            Law law(par);
        }
        catch (const eos::ParameterError& err)
        {
            range = eos::validRangeOf(err.what(), first.first());
        }
        FatalIOErrorInFunction(dict)
            << "entry '" << first.first() << "' = '" << first.second().c_str()
            << "' is not a number"
            << (range.empty() ? "" : "; valid range " + range).c_str()
            << exit(FatalIOError);
    }

    //- The valid range of coefficient key of Law ("" for another key):
    //  the law's check of a value outside every range in its place, in a
    //  valid set
    template<class Law>
    std::string lawRange
    (
        const std::string& key,
        const std::vector
        <
            std::pair<const char*, double Law::Parameters::*>
        >& fields
    )
    {
        for (const auto& f : fields)
        {
            if (key != f.first)
            {
                continue;
            }
            typename Law::Parameters par;
            par.*(f.second) = eos::outsideEveryRange();
            try
            {
                Law law(par);
            }
            catch (const eos::ParameterError& err)
            {
                return eos::validRangeOf(err.what(), key);
            }
        }
        return std::string();
    }

    //- The scan of the numbers' range of a coefficient of
    //  constant/thermophysicalProperties (<law>Coeffs/<key>; adv48a h08:
    //  the reader's limits only)
    std::string thermoRange
    (
        const std::string& dictName,
        const std::vector<std::string>& scope,
        const std::string& key
    )
    {
        if (dictName != "thermophysicalProperties" || scope.size() != 1)
        {
            return std::string();
        }
        typedef eos::MieGruneisen::Parameters mg;
        typedef eos::StiffenedGas::Parameters sg;
        typedef eos::IdealGas::Parameters ig;
        if (scope[0] == word(eos::MieGruneisen::typeName) + "Coeffs")
        {
            return lawRange<eos::MieGruneisen>
            (
                key,
                {
                    {"rho0", &mg::rho0}, {"C0", &mg::C0}, {"s", &mg::s},
                    {"Gamma0", &mg::Gamma0}, {"Cv", &mg::Cv},
                    {"T0", &mg::T0}
                }
            );
        }
        if (scope[0] == word(eos::StiffenedGas::typeName) + "Coeffs")
        {
            return lawRange<eos::StiffenedGas>
            (
                key,
                {{"gamma", &sg::gamma}, {"pInf", &sg::pInf}, {"Cv", &sg::Cv}}
            );
        }
        if (scope[0] == word(eos::IdealGas::typeName) + "Coeffs")
        {
            return lawRange<eos::IdealGas>
            (
                key, {{"gamma", &ig::gamma}, {"Cv", &ig::Cv}}
            );
        }
        return std::string();
    }

    const bool thermoRangeAdded = foamTools::addScanRange(thermoRange);

    //- Read a coefficient [SI], optionally preceded by its dimensions,
    //  which must then match dims (a FatalIOError naming the entry, not
    //  the abort of dimensioned<Type>::initialize); nothing after it
    scalar readCoeff
    (
        const dictionary& dict,
        const word& name,
        const dimensionSet& dims
    )
    {
        ITstream& is = dict.lookup(name);
        token t(is);
        is.putBack(t);
        if (t.isPunctuation() && t.pToken() == token::BEGIN_SQR)
        {
            const dimensionSet given(is);
            if (given != dims)
            {
                FatalIOErrorInFunction(dict)
                    << "Coefficient " << name << " has dimensions " << given
                    << "; expected " << dims << exit(FatalIOError);
            }
        }
        // nan, inf (words to OpenFOAM's reader: "Wrong token type", no
        // range, adv42 g25) or another word: named by checkNumbers with
        // the law's range, a value outside every range in its place
        const token v(is);
        if (!v.isNumber())
        {
            OStringStream text;
            text << v;
            notNumbers().append(Pair<word>(name, text.str()));
            return eos::outsideEveryRange();
        }
        const scalar value = v.number();
        is.check(FUNCTION_NAME);
        OStringStream expected;
        expected
            << "one number (SI), optionally preceded by its dimensions "
            << dims;
        foamTools::checkEntryEnd(dict, name, is, expected.str());
        return value;
    }
}


template<>
wordList rhoEThermoModel<eos::MieGruneisen>::coeffNames()
{
    return {"rho0", "C0", "s", "Gamma0", "Cv", "T0"};
}


template<>
eos::MieGruneisen::Parameters
rhoEThermoModel<eos::MieGruneisen>::readParameters(const dictionary& dict)
{
    eos::MieGruneisen::Parameters par;
    par.rho0 = readCoeff(dict, "rho0", dimDensity);
    par.C0 = readCoeff(dict, "C0", dimVelocity);
    par.s = readCoeff(dict, "s", dimless);
    par.Gamma0 = readCoeff(dict, "Gamma0", dimless);
    par.Cv = readCoeff(dict, "Cv", dimEnergy/dimMass/dimTemperature);
    par.T0 = readCoeff(dict, "T0", dimTemperature);
    checkNumbers<eos::MieGruneisen>(dict, par);
    // Inside the valid range but not a liquid's or solid's value: other
    // units, likely (adv37 w79); said now and in an invalid state's message
    rhoEThermo::implausibleNote() = eos::MieGruneisen::implausible(par);
    if (!rhoEThermo::implausibleNote().empty())
    {
        WarningInFunction
            << dict.name().c_str() << ": "
            << rhoEThermo::implausibleNote().c_str() << nl << endl;
    }
    return par;
}


template<>
wordList rhoEThermoModel<eos::StiffenedGas>::coeffNames()
{
    return {"gamma", "pInf", "Cv"};
}


template<>
eos::StiffenedGas::Parameters
rhoEThermoModel<eos::StiffenedGas>::readParameters(const dictionary& dict)
{
    eos::StiffenedGas::Parameters par;
    par.gamma = readCoeff(dict, "gamma", dimless);
    par.pInf = readCoeff(dict, "pInf", dimPressure);
    par.Cv = readCoeff(dict, "Cv", dimEnergy/dimMass/dimTemperature);
    checkNumbers<eos::StiffenedGas>(dict, par);
    return par;
}


template<>
wordList rhoEThermoModel<eos::IdealGas>::coeffNames()
{
    return {"gamma", "Cv"};
}


template<>
eos::IdealGas::Parameters
rhoEThermoModel<eos::IdealGas>::readParameters(const dictionary& dict)
{
    eos::IdealGas::Parameters par;
    par.gamma = readCoeff(dict, "gamma", dimless);
    par.Cv = readCoeff(dict, "Cv", dimEnergy/dimMass/dimTemperature);
    checkNumbers<eos::IdealGas>(dict, par);
    return par;
}


#define makeRhoEThermoModel(Law)                                              \
    typedef rhoEThermoModel<eos::Law> rhoEThermo##Law;                        \
    defineTemplateTypeNameAndDebugWithName                                    \
    (                                                                         \
        rhoEThermo##Law,                                                      \
        eos::Law::typeName,                                                   \
        0                                                                     \
    );                                                                        \
    addToRunTimeSelectionTable(rhoEThermo, rhoEThermo##Law, mesh)

makeRhoEThermoModel(MieGruneisen);
makeRhoEThermoModel(StiffenedGas);
makeRhoEThermoModel(IdealGas);

#undef makeRhoEThermoModel

} // End namespace Foam
