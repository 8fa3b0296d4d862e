#include "SolidError.H"
#include "numberText.H"

#include <cmath>
#include <sstream>

void solid::checkParameter
(
    const std::string& context,
    const std::string& entry,
    double value,
    double lo,
    double hi,
    const std::string& unit,
    bool loInclusive
)
{
    const bool okLo = loInclusive ? value >= lo : value > lo;
    if (!(okLo && value < hi) || !std::isfinite(value))
    {
        std::ostringstream os;
        os  << context << ": entry '" << entry << "' = "
            << numberText::shortest(value) << " "
            << unit << " is outside the valid range "
            << (loInclusive ? "[" : "(") << lo << ", " << hi << ")";
        throw SolidError(SolidError::Kind::parameter, os.str());
    }
}
