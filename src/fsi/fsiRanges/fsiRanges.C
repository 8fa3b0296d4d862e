#include "fsiRanges.H"

#include <utility>
#include <vector>

namespace
{

typedef Foam::foamTools::numberRange numberRange;

// scope, key, range: constant/fsiProperties' numbers
const std::vector<std::pair<std::pair<std::string, std::string>, numberRange>>&
table()
{
    const Foam::scalar inf = Foam::foamTools::noUpperBound<Foam::scalar>();
    static const
        std::vector<std::pair<std::pair<std::string, std::string>, numberRange>>
        rows
    {
        // couplingScheme: a relative residual; 0.1 already lets a pass
        // with a tenth of the interface velocity wrong count as converged
        {{"coupling", "maxIter"}, {1, inf, true, true, ""}},
        {{"coupling", "tolerance"}, {0, 0.1, false, true, ""}},
        {{"coupling", "velocityScale"}, {0, inf, false, true, "m/s"}},
        // aitken, IQNILS
        {{"coupling", "initialRelaxation"}, {0, 1, false, true, ""}},
        {{"coupling", "reuse"}, {0, inf, true, true, ""}},
        // fluidSolidInteraction
        {{"coupling", "solidSubcycles"}, {1, 1000, true, true, ""}},
        // interfaceMap
        {{"interface", "mapTolerance"}, {0, inf, false, true, ""}},
        {{"interface", "pressureQuadrature"}, {1, 16, true, true, ""}},
        // interfaceMotion
        {{"interface", "motionDistance"}, {0, inf, false, true, "m"}},
        {{"interface", "motionNearest"}, {1, inf, true, true, ""}},
        // constant/solidProperties' entries the FSI solid reads
        // (solidDomain): fractions of the explicit solver's settings, the
        // probes' radius, interfaceProbe, the interface patches
        {{"solidProperties", "explicitSafety"}, {0, 1, false, false, ""}},
        {{"solidProperties", "hourglassViscosity"}, {0, 1, true, false, ""}},
        {{"solidProperties", "shearViscosity"}, {0, 1, true, false, ""}},
        {
            {"solidProperties/hourglassViscosityRegions", ""},
            {0, 1, true, false, ""}
        },
        {{"solidProperties/probes", "radius"}, {0, inf, true, true, "m"}},
        {
            {"solidProperties/interfaceProbe", "heightFraction"},
            {0, 1, false, false, ""}
        },
        {
            {"solidProperties", "interfacePatchLength"},
            {0, inf, false, true, "m"}
        }
    };
    return rows;
}

// The row of key in scope; a row of key "" holds every key of its scope
// (hourglassViscosityRegions' region names)
const numberRange* find(const std::string& scope, const std::string& key)
{
    for (const auto& row : table())
    {
        if
        (
            row.first.first == scope
         && (row.first.second == key || row.first.second.empty())
        )
        {
            return &row.second;
        }
    }
    return nullptr;
}

// The scan of the numbers' range of an entry of constant/fsiProperties
// (coupling, interface) or of the FSI solid's entries of
// constant/solidProperties (the materials' are solidInput's)
std::string fsiPropertiesRange
(
    const std::string& dictName,
    const std::vector<std::string>& scope,
    const std::string& key
)
{
    const numberRange* r = nullptr;
    if (dictName == "fsiProperties" && scope.size() == 1)
    {
        r = find(scope[0], key);
    }
    else if (dictName == "solidProperties" && scope.empty())
    {
        r = find(dictName, key);
    }
    else if
    (
        dictName == "solidProperties"
     && (scope.size() == 1 || (scope.size() == 2 && scope[0] == "probes"))
    )
    {
        // a probe's sub-dictionary is named by the probe
        r = find(dictName + "/" + scope[0], key);
    }
    return r ? r->text() : std::string();
}

const bool fsiPropertiesRangeAdded =
    Foam::foamTools::addScanRange(fsiPropertiesRange);

} // End anonymous namespace


const Foam::foamTools::numberRange& Foam::fsiRanges::range
(
    const word& scope,
    const word& key
)
{
    const numberRange* r = find(scope, key);
    if (!r)
    {
        FatalErrorInFunction
            << "no range of entry '" << key << "' of fsiProperties' "
            << scope << " in fsiRanges (a bug)" << exit(FatalError);
    }
    return *r;
}


// ************************************************************************* //
