// libFuzzer harness: the material parameter reader of the solid library
// (MaterialParameters::fromEntries of StringEntries: the "key value"
// entries of a region sub-dictionary as text, strictly parsed). Each line
// of the input is "key value..." (the paper's parameter sets are data
// files, etc/caseDicts/cellMaterials, read by the same reader). Any bad
// input must throw SolidError; accepted parameters must build a Material.
#include "Material.H"
#include "SolidError.H"
#include "StringEntries.H"

#include <cstdint>
#include <map>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    std::istringstream is(std::string(reinterpret_cast<const char*>(data),
                                      size));
    std::string line;
    std::map<std::string, std::string> entries;
    while (std::getline(is, line))
    {
        const auto k = line.find(' ');
        if (k == std::string::npos) continue;
        entries[line.substr(0, k)] = line.substr(k + 1);
    }
    try
    {
        const auto p = solid::MaterialParameters::fromEntries
        (
            "fuzz", solid::StringEntries("material 'fuzz'", entries)
        );
        solid::Material::create(p);
    }
    catch (const solid::SolidError&)
    {
    }
    return 0;
}
