/*---------------------------------------------------------------------------*\
    riemann::AnyEos selection
\*---------------------------------------------------------------------------*/

#include "anyEos.H"
#include "inputError.H"

namespace riemann
{

namespace
{

const std::map<std::string, std::vector<coefficientInfo>>& coefficientTable()
{
    static const std::map<std::string, std::vector<coefficientInfo>> table
    {
        {
            eos::MieGruneisen::typeName,
            {
                {"rho0", "kg/m^3"}, {"C0", "m/s"}, {"s", "-"},
                {"Gamma0", "-"}, {"Cv", "J/kg/K"}, {"T0", "K"}
            }
        },
        {
            eos::StiffenedGas::typeName,
            {{"gamma", "-"}, {"pInf", "Pa"}, {"Cv", "J/kg/K"}}
        },
        {
            eos::IdealGas::typeName,
            {{"gamma", "-"}, {"Cv", "J/kg/K"}}
        }
    };
    return table;
}

std::string joined(const std::vector<std::string>& names)
{
    std::string s;
    for (const auto& n : names)
    {
        s += (s.empty() ? "" : " ") + n;
    }
    return s;
}

} // namespace


std::vector<std::string> eosNames()
{
    return
    {
        eos::MieGruneisen::typeName,
        eos::StiffenedGas::typeName,
        eos::IdealGas::typeName
    };
}


std::string eosName(const AnyEos& law)
{
    return std::visit
    (
        [](const auto& l) -> std::string
        {
            return std::decay_t<decltype(l)>::typeName;
        },
        law
    );
}


const std::vector<coefficientInfo>& eosCoefficients(const std::string& name)
{
    const auto it = coefficientTable().find(name);
    if (it == coefficientTable().end())
    {
        throw inputError
        (
            "unknown equation of state '" + name + "'; valid laws: "
          + joined(eosNames())
        );
    }
    return it->second;
}


AnyEos selectEos
(
    const std::string& name,
    const std::map<std::string, double>& coefficients
)
{
    const auto& info = eosCoefficients(name);
    std::vector<std::string> valid;
    for (const auto& c : info)
    {
        valid.push_back(c.name + " [" + c.unit + "]");
        if (!coefficients.count(c.name))
        {
            throw inputError
            (
                "missing coefficient '" + c.name + "' [" + c.unit
              + "] of the law " + name
            );
        }
    }
    for (const auto& kv : coefficients)
    {
        bool known = false;
        for (const auto& c : info) known = known || c.name == kv.first;
        if (!known)
        {
            throw inputError
            (
                "unknown coefficient '" + kv.first + "' of the law " + name
              + "; valid coefficients: " + joined(valid)
            );
        }
    }

    const auto& k = coefficients;
    if (name == eos::MieGruneisen::typeName)
    {
        return eos::MieGruneisen
        (
            {
                k.at("rho0"), k.at("C0"), k.at("s"), k.at("Gamma0"),
                k.at("Cv"), k.at("T0")
            }
        );
    }
    if (name == eos::StiffenedGas::typeName)
    {
        return eos::StiffenedGas({k.at("gamma"), k.at("pInf"), k.at("Cv")});
    }
    return eos::IdealGas({k.at("gamma"), k.at("Cv")});
}

} // namespace riemann
