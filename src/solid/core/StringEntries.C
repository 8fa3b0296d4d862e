#include "StringEntries.H"
#include "SolidError.H"

#include <cmath>
#include <cstdlib>


solid::StringEntries::StringEntries
(
    const std::string& name,
    const std::map<std::string, std::string>& entries
)
:
    name_(name),
    entries_(entries)
{}


const std::string& solid::StringEntries::text(const std::string& key) const
{
    const auto it = entries_.find(key);
    if (it == entries_.end())
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            name_ + ": missing entry '" + key + "'"
        );
    }
    return it->second;
}


bool solid::StringEntries::has(const std::string& key) const
{
    return entries_.count(key) > 0;
}


double solid::StringEntries::real(const std::string& key) const
{
    const std::string& value = text(key);
    // strtod alone would skip leading blanks and accept hexadecimal
    // numbers, "inf" and "nan"
    const bool decimal =
        !value.empty()
     && value.find_first_not_of("0123456789.eE+-") == std::string::npos;
    char* end = nullptr;
    const double v = decimal ? std::strtod(value.c_str(), &end) : 0;
    if (!decimal || end != value.c_str() + value.size() || !std::isfinite(v))
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            name_ + ": entry '" + key + "' = '" + value
          + "' is not a number"
        );
    }
    return v;
}


std::string solid::StringEntries::word(const std::string& key) const
{
    const std::string& value = text(key);
    if (value.empty() || value.find_first_of(" \t\n") != std::string::npos)
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            name_ + ": entry '" + key + "' = '" + value + "' is not a word"
        );
    }
    return value;
}


std::vector<std::string> solid::StringEntries::keys() const
{
    std::vector<std::string> k;
    for (const auto& kv : entries_) k.push_back(kv.first);
    return k;
}
