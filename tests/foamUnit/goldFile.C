#include "goldFile.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

Foam::foamUnit::goldFile::goldFile(const word& suite)
{
    const char* dir = std::getenv("PROJECT_DIR");
    if (!dir || !*dir)
    {
        ADD_FAILURE()
            << "PROJECT_DIR is not set: source etc/bashrc of the project";
        return;
    }
    file_ = fileName(dir)/"tests"/"foamUnit"/"gold"/(suite + ".dat");
    std::ifstream is(file_);
    if (!is)
    {
        ADD_FAILURE() << "Cannot read the gold file " << file_;
        return;
    }
    std::string line;
    for (label lineNo = 1; std::getline(is, line); ++lineNo)
    {
        line = line.substr(0, line.find('#'));
        std::istringstream ls(line);
        std::string key;
        if (!(ls >> key))
        {
            continue;
        }
        entry e;
        std::string rest;
        if (!(ls >> e.value >> e.tolerance >> e.unit) || (ls >> rest))
        {
            ADD_FAILURE()
                << file_ << ":" << lineNo << ": expected 'key value"
                << " tolerance unit', found '" << line << "'";
            continue;
        }
        if (!(e.tolerance >= 0))
        {
            ADD_FAILURE()
                << file_ << ":" << lineNo << ": tolerance " << e.tolerance
                << " of " << key << " is outside the valid range [0, inf)";
        }
        if (!entries_.emplace(key, e).second)
        {
            ADD_FAILURE()
                << file_ << ":" << lineNo << ": " << key << " given twice";
        }
    }
}


Foam::foamUnit::goldFile::entry Foam::foamUnit::goldFile::operator[]
(
    const std::string& key
) const
{
    const auto it = entries_.find(key);
    if (it == entries_.end())
    {
        ADD_FAILURE() << "No entry " << key << " in the gold file " << file_;
        const scalar nan = std::numeric_limits<scalar>::quiet_NaN();
        return entry{nan, nan, "?"};
    }
    return it->second;
}


void Foam::foamUnit::goldFile::check
(
    const std::string& key,
    const scalar measured
) const
{
    const entry e = (*this)[key];
    EXPECT_TRUE(std::abs(measured - e.value) <= e.tolerance)
        << key << " = " << measured << " " << e.unit << "; gold "
        << e.value << " +- " << e.tolerance << " " << e.unit
        << " (" << file_ << ")";
}
