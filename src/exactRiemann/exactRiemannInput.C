/*---------------------------------------------------------------------------*\
    riemann::exactRiemannInput
\*---------------------------------------------------------------------------*/

#include "exactRiemannInput.H"
#include "inputError.H"
#include "closestKeyword.H"
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

namespace riemann
{

namespace
{

//- A parsed number or an inputError naming the entry
double number
(
    const exactRiemannInput::entryTable& entries,
    const std::string& key
)
{
    const auto it = entries.find(key);
    if (it == entries.end())
    {
        throw inputError("missing entry '" + key + "'");
    }
    std::istringstream is(it->second);
    double v;
    char extra;
    if (!(is >> v) || (is >> extra))
    {
        throw inputError
        (
            "entry '" + key + "' = '" + it->second + "' is not a number"
        );
    }
    return v;
}

//- A number inside (lo, hi) (finite if the bounds are infinite)
double numberIn
(
    const exactRiemannInput::entryTable& entries,
    const std::string& key,
    double lo,
    double hi,
    const std::string& unit
)
{
    const double v = number(entries, key);
    if (!std::isfinite(v) || !(v > lo) || !(v < hi))
    {
        std::ostringstream os;
        os  << "entry '" << key << "' = " << entries.at(key) << " " << unit
            << " is outside the valid range (" << lo << ", " << hi << ")";
        throw inputError(os.str());
    }
    return v;
}

void trim(std::string& s)
{
    const auto b = s.find_first_not_of(" \t\r");
    const auto e = s.find_last_not_of(" \t\r");
    s = b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

const std::vector<std::string> stateKeys
{
    "law", "rhoL", "uL", "pL", "rhoR", "uR", "pR",
    "x0", "t", "xMin", "xMax", "n"
};

} // namespace


void exactRiemannInput::read
(
    std::istream& is,
    const std::string& source,
    entryTable& entries
)
{
    // A key given twice in one file is an error (the last would win
    // silently); a command-line key=value replaces the file's on purpose
    std::map<std::string, int> firstLine;
    std::string line;
    for (int lineNo = 1; std::getline(is, line); ++lineNo)
    {
        // A UTF-8 byte-order mark (an editor's) would join the first key
        // and be taken for an unknown one ("missing entry 'law'", adv52
        // p27): named
        if (lineNo == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0)
        {
            throw inputError
            (
                source + ":1: the file starts with a UTF-8 byte-order mark"
                " (the bytes EF BB BF): save it as plain text without it"
                " (e.g. sed -i '1s/^\\xEF\\xBB\\xBF//' " + source + ")"
            );
        }
        for (const char* comment : {"//", "#"})
        {
            const auto c = line.find(comment);
            if (c != std::string::npos) line.erase(c);
        }
        std::istringstream statements(line);
        std::string statement;
        while (std::getline(statements, statement, ';'))
        {
            trim(statement);
            if (statement.empty()) continue;
            std::istringstream words(statement);
            std::string key, value, extra;
            words >> key >> value;
            if (value.empty() || (words >> extra))
            {
                throw inputError
                (
                    source + ":" + std::to_string(lineNo) + ": expected "
                    "'key value', got '" + statement + "'"
                );
            }
            const auto seen = firstLine.emplace(key, lineNo);
            if (!seen.second)
            {
                throw inputError
                (
                    source + ":" + std::to_string(lineNo) + ": entry '" + key
                  + "' is given twice (first on line "
                  + std::to_string(seen.first->second) + "): give it once"
                );
            }
            entries[key] = value;
        }
    }
}


void exactRiemannInput::readArgument
(
    const std::string& arg,
    entryTable& entries
)
{
    const auto eq = arg.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == arg.size())
    {
        throw inputError
        (
            "argument '" + arg + "' is not of the form key=value"
        );
    }
    entries[arg.substr(0, eq)] = arg.substr(eq + 1);
}


void exactRiemannInput::readArgument
(
    const std::string& arg,
    entryTable& entries,
    std::set<std::string>& given
)
{
    const auto eq = arg.find('=');
    if (eq != std::string::npos && eq != 0 && eq + 1 != arg.size()
     && !given.insert(arg.substr(0, eq)).second)
    {
        throw inputError
        (
            "argument '" + arg + "': the key '" + arg.substr(0, eq)
          + "' is given twice as an argument (the later would replace the"
            " earlier without a word): give it once"
        );
    }
    readArgument(arg, entries);
}


exactRiemannInput::exactRiemannInput(const entryTable& entries)
:
    law_(eos::IdealGas({}))
{
    const double inf = std::numeric_limits<double>::infinity();

    const auto lawIt = entries.find("law");
    if (lawIt == entries.end())
    {
        std::string names;
        for (const auto& n : eosNames()) names += " " + n;
        throw inputError("missing entry 'law'; valid laws:" + names);
    }
    const std::string& lawName = lawIt->second;

    // Every key is either a state entry or a coefficient of the law
    std::map<std::string, double> coeffs;
    const auto& info = eosCoefficients(lawName);
    const std::set<std::string> known(stateKeys.begin(), stateKeys.end());
    for (const auto& kv : entries)
    {
        bool isCoeff = false;
        for (const auto& c : info)
        {
            if (c.name == kv.first)
            {
                coeffs[c.name] = numberIn(entries, c.name, -inf, inf, c.unit);
                isCoeff = true;
            }
        }
        if (!isCoeff && !known.count(kv.first))
        {
            std::vector<std::string> names(stateKeys);
            for (const auto& c : info) names.push_back(c.name);
            std::string valid;
            for (const auto& k : names) valid += " " + k;
            throw inputError
            (
                "unknown entry '" + kv.first + "'"
              + keywords::didYouMean(kv.first, names)
              + "; valid entries for law " + lawName + ":" + valid
            );
        }
    }
    law_ = selectEos(lawName, coeffs);

    left_ =
    {
        numberIn(entries, "rhoL", 0, inf, "kg/m^3"),
        numberIn(entries, "uL", -inf, inf, "m/s"),
        numberIn(entries, "pL", -inf, inf, "Pa")
    };
    right_ =
    {
        numberIn(entries, "rhoR", 0, inf, "kg/m^3"),
        numberIn(entries, "uR", -inf, inf, "m/s"),
        numberIn(entries, "pR", -inf, inf, "Pa")
    };
    x0_ = numberIn(entries, "x0", -inf, inf, "m");
    t_ = numberIn(entries, "t", 0, inf, "s");
    xMin_ = numberIn(entries, "xMin", -inf, inf, "m");
    xMax_ = numberIn(entries, "xMax", xMin_, inf, "m");

    const double n = numberIn(entries, "n", 1, 1e7 + 1, "-");
    if (n != std::floor(n))
    {
        throw inputError
        (
            "entry 'n' = " + entries.at("n") + " must be an integer in "
            "[2, 10000000]"
        );
    }
    n_ = static_cast<int>(n);
}


std::vector<double> exactRiemannInput::points() const
{
    std::vector<double> x(n_);
    for (int i = 0; i < n_; ++i)
    {
        x[i] = xMin_ + (xMax_ - xMin_)*i/(n_ - 1);
    }
    return x;
}

} // namespace riemann
