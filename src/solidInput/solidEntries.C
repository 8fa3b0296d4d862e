#include "solidEntries.H"
#include "OStringStream.H"

#include "SolidError.H"
#include "messageText.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::solidEntries::solidEntries
(
    const dictionary& dict,
    const std::string& name
)
:
    dict_(dict),
    name_(name)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::solidEntries::fail
(
    const std::string& key,
    const std::string& why
) const
{
    // The entry's text for the message only: its value is never parsed
    // back from it
    OStringStream os;
    const entry* e = dict_.findEntry(key, keyType::LITERAL);
    if (e && e->isDict())
    {
        os << "{ ... }";
    }
    else if (e)
    {
        const ITstream& is = e->stream();
        forAll(is, i)
        {
            os << (i ? " " : "") << foamTools::tokenText(is[i]).c_str();
        }
    }
    throw solid::SolidError
    (
        solid::SolidError::Kind::parameter,
        name_ + ": entry '" + key + "' = '" + os.str() + "' " + why
    );
}


const Foam::token& Foam::solidEntries::single(const std::string& key) const
{
    const entry* e = dict_.findEntry(key, keyType::LITERAL);
    if (!e)
    {
        throw solid::SolidError
        (
            solid::SolidError::Kind::parameter,
            name_ + ": missing entry '" + key + "'"
        );
    }
    if (e->isDict())
    {
        fail(key, "must be a value, not a sub-dictionary");
    }
    const ITstream& is = e->stream();
    if (is.size() != 1)
    {
        fail(key, "must be one value");
    }
    return is[0];
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

const std::string& Foam::solidEntries::name() const
{
    return name_;
}


bool Foam::solidEntries::has(const std::string& key) const
{
    return dict_.found(key, keyType::LITERAL);
}


double Foam::solidEntries::real(const std::string& key) const
{
    // '-inf', '+1', '0x10': more than one token, as the readers of the
    // other dictionaries say (adv48a h08: "'- inf' must be one value")
    const entry* e = dict_.findEntry(key, keyType::LITERAL);
    if (e && !e->isDict() && e->stream().size() > 1)
    {
        const std::string n(std::to_string(e->stream().size()));
        fail
        (
            key,
            e->stream()[0].isPunctuation()
          ? "is not a number (read as " + n + " tokens: write one number,"
            " without a '+' sign or a prefix such as 0x)"
          : "must be one value (read as " + n + " tokens: write the number"
            " alone, in SI units)"
        );
    }
    if (!single(key).isNumber())
    {
        fail(key, "is not a number");
    }
    const scalar v = dict_.get<scalar>(key, keyType::LITERAL);
    if (!std::isfinite(v))
    {
        fail(key, "is not a number");
    }
    return v;
}


std::string Foam::solidEntries::word(const std::string& key) const
{
    const token& t = single(key);
    if (!t.isWord() && !t.isString())
    {
        fail(key, "is not a word");
    }
    return dict_.get<Foam::word>(key, keyType::LITERAL);
}


std::vector<std::string> Foam::solidEntries::keys() const
{
    std::vector<std::string> k;
    for (const entry& e : dict_)
    {
        k.push_back(e.keyword());
    }
    std::sort(k.begin(), k.end());
    return k;
}


// ************************************************************************* //
