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
            << (loInclusive ? "[" : "(") << lo << ", " << hi << ")"
            // the unit after the range too (adv48a h08: "0 Pa is outside
            // the valid range (0, 1e+13)"), none for a pure number ("-")
            << (unit.empty() || unit == "-" ? "" : " " + unit);
        throw SolidError(SolidError::Kind::parameter, os.str());
    }
}
