#include "Material.H"
#include "NeoHookean.H"
#include "QuadraticVolumetric.H"
#include "MieGruneisenVolumetric.H"
#include "SolidError.H"
#include "physicalBounds.H"
#include "closestKeyword.H"
#include "eosStatus.H"

#include <cstdlib>
#include <limits>
#include <set>


solid::MaterialParameters solid::MaterialParameters::fromEntries
(
    const std::string& name,
    const Entries& entries
)
{
    MaterialParameters par;
    par.name = name;
    const std::string ctx = "material '" + name + "'";
    std::map<int, double> mu, tau, eta;
    std::string notNumber, notNumberWhy;
    const std::map<std::string, double*> scalars =
    {
        {"rho0", &par.rho0}, {"C10", &par.C10}, {"d0", &par.d0},
        {"C0", &par.eos.C0}, {"s", &par.eos.s}, {"Gamma0", &par.eos.Gamma0},
        {"Cv", &par.eos.Cv}, {"T0", &par.eos.T0}, {"b1", &par.b1},
        {"b2", &par.b2}
    };
    for (const std::string& key : entries.keys())
    {
        if (key == "volumetric")
        {
            par.volumetric = entries.word(key);
            continue;
        }
        if (key == "c0")
        {
            // Renamed: c0 beside the Mie-Grueneisen C0 read as one name
            throw SolidError
            (
                SolidError::Kind::parameter,
                ctx + ": entry 'c0' is now 'C10' (the neo-Hookean "
                "coefficient C10 = mu0/2, the paper's c_0; C0 is the "
                "Mie-Grueneisen sound speed)"
            );
        }
        const auto it = scalars.find(key);
        if (it != scalars.end())
        {
            try
            {
                *it->second = entries.real(key);
            }
            catch (const SolidError& err)
            {
                // nan, inf, a word: refused below with the entry's valid
                // range (adv42 g25: d0, C0, Gamma0 "is not a number", no
                // range), a value outside every range in its place
                if (notNumber.empty())
                {
                    notNumber = key;
                    notNumberWhy = err.what();
                }
                *it->second = eos::outsideEveryRange();
            }
            continue;
        }
        bool branch = false;
        for (const char* prefix : {"mu", "tau", "eta"})
        {
            const std::string pre(prefix);
            if
            (
                key.size() > pre.size() && key.compare(0, pre.size(), pre) == 0
             && key.find_first_not_of("0123456789", pre.size())
                == std::string::npos
            )
            {
                const int n = std::atoi(key.c_str() + pre.size());
                // not a number: refused below with its valid range, as
                // the scalars (adv48a h08: mu1 inf "is not a number", no
                // range nor unit)
                double v = eos::outsideEveryRange();
                try
                {
                    v = entries.real(key);
                }
                catch (const SolidError& err)
                {
                    if (notNumber.empty())
                    {
                        notNumber = key;
                        notNumberWhy = err.what();
                    }
                }
                if (n < 1)
                {
                    throw SolidError
                    (
                        SolidError::Kind::parameter,
                        ctx + ": entry '" + key + "': branches are numbered "
                        "from 1"
                    );
                }
                (pre == "mu" ? mu : pre == "tau" ? tau : eta)[n] = v;
                branch = true;
            }
        }
        if (!branch)
        {
            // The closest of the names, the branches' numbered as the key
            // is (tua2: tau2), else as branch 1
            const auto d = key.find_last_not_of("0123456789");
            const std::string n =
                d + 1 < key.size() ? key.substr(d + 1) : std::string("1");
            std::vector<std::string> names{"volumetric"};
            std::string valid;
            for (const auto& s : scalars)
            {
                names.push_back(s.first);
                valid += s.first + " ";
            }
            for (const char* prefix : {"mu", "tau", "eta"})
            {
                names.push_back(prefix + n);
            }
            throw SolidError
            (
                SolidError::Kind::parameter,
                ctx + ": unknown entry '" + key + "'"
              + keywords::didYouMean(key, names) + "; valid entries: "
              + valid + "volumetric muN tauN etaN (N = 1, 2, ...)"
            );
        }
    }
    par.eos.rho0 = par.rho0;
    std::set<int> ids;
    for (const auto& m : mu) ids.insert(m.first);
    for (const auto& m : tau) ids.insert(m.first);
    for (const auto& m : eta) ids.insert(m.first);
    int expect = 1;
    // A branch's check of an entry that is not a number (its value outside
    // every range in its place) gives that entry's range
    try
    {
        for (const int n : ids)
        {
            const std::string sn = std::to_string(n);
            if (n != expect++)
            {
                throw SolidError
                (
                    SolidError::Kind::parameter,
                    ctx + ": Maxwell branches must be numbered 1, 2, ... "
                    "without gaps (found branch " + sn + ")"
                );
            }
            if (!mu.count(n))
            {
                throw SolidError
                (
                    SolidError::Kind::parameter,
                    ctx + ": entry 'mu" + sn + "' missing for branch " + sn
                );
            }
            if (tau.count(n) == eta.count(n))
            {
                throw SolidError
                (
                    SolidError::Kind::parameter,
                    ctx + ": give exactly one of 'tau" + sn + "' and 'eta" + sn
                  + "' for branch " + sn
                );
            }
            MaxwellBranch b;
            b.mu = mu[n];
            if (tau.count(n))
            {
                b.tau = tau[n];
            }
            else
            {
                checkParameter
                (
                    ctx, "eta" + sn, eta[n], 0, physicalBounds::viscosityMax,
                    "Pa s"
                );
                checkParameter
                (
                    ctx, "mu" + sn, b.mu, 0, physicalBounds::modulusMax, "Pa"
                );
                b.tau = eta[n]/b.mu;
            }
            par.branches.push_back(b);
        }
    }
    catch (const SolidError& err)
    {
        const std::string range
        (
            notNumber.empty()
          ? std::string() : eos::validRangeOf(err.what(), notNumber)
        );
        if (range.empty())
        {
            throw;
        }
        throw SolidError
        (
            SolidError::Kind::parameter, notNumberWhy + "; valid range " + range
        );
    }
    // The first entry that is not a number, with its valid range: the one
    // the law's check gives in its place (none for an entry the law does
    // not read)
    if (!notNumber.empty())
    {
        std::string range;
        try
        {
            Material::create(par);
        }
        catch (const std::exception& err)
        {
            range = eos::validRangeOf(err.what(), notNumber);
        }
        throw SolidError
        (
            SolidError::Kind::parameter,
            notNumberWhy + (range.empty() ? "" : "; valid range " + range)
        );
    }
    // Validate now so that errors point at the dictionary
    Material::create(par);
    // The law's coefficients are required, as the fluid's thermo requires
    // them (issue 19: a missing one was water's default, silently)
    if (par.volumetric == "mieGruneisen")
    {
        std::string missing;
        for (const char* key : {"C0", "s", "Gamma0", "Cv", "T0"})
        {
            if (!entries.has(key))
            {
                missing += std::string(missing.empty() ? "" : " ") + key;
            }
        }
        if (!missing.empty())
        {
            throw SolidError
            (
                SolidError::Kind::parameter,
                ctx + ": volumetric mieGruneisen needs every coefficient of "
                "the law (C0 [m/s] s [-] Gamma0 [-] Cv [J/(kg K)] T0 [K]); "
                "missing: " + missing
            );
        }
    }
    return par;
}


solid::Material::Material
(
    const std::string& name,
    double rho0,
    std::unique_ptr<IsochoricModel> iso,
    std::unique_ptr<VolumetricLaw> vol
)
:
    name_(name),
    rho0_(rho0),
    iso_(std::move(iso)),
    vol_(std::move(vol))
{
    checkParameter
    (
        "material '" + name + "'", "rho0", rho0, physicalBounds::rhoMin,
        physicalBounds::rhoMax, "kg/m^3", true
    );
}


std::unique_ptr<solid::Material> solid::Material::create
(
    const MaterialParameters& par
)
{
    const std::string ctx = "material '" + par.name + "'";
    checkParameter
    (
        ctx, "rho0", par.rho0, physicalBounds::rhoMin, physicalBounds::rhoMax,
        "kg/m^3", true
    );

    std::unique_ptr<IsochoricModel> iso(new NeoHookean(par.C10, ctx));
    if (!par.branches.empty())
    {
        iso.reset(new Viscoelastic(std::move(iso), par.branches, ctx));
    }

    std::unique_ptr<VolumetricLaw> vol;
    if (par.volumetric == "quadratic")
    {
        checkParameter
        (
            ctx, "d0", par.d0, 0, physicalBounds::d0Max, "1/Pa", true
        );
        if (par.d0 == 0)
        {
            vol.reset(new IncompressibleVolumetric);
        }
        else
        {
            vol.reset(new QuadraticVolumetric(par.d0, par.rho0, ctx));
        }
    }
    else if (par.volumetric == "mieGruneisen")
    {
        eos::MieGruneisen::Parameters e = par.eos;
        e.rho0 = par.rho0;
        vol.reset(new MieGruneisenVolumetric(e, par.b1, par.b2, ctx));
    }
    else if (par.volumetric == "neoHookean")
    {
        // Renamed: the law is the paper's quadratic (J-1)^2/d0, not
        // neo-Hookean
        throw SolidError
        (
            SolidError::Kind::parameter,
            ctx + ": volumetric law 'neoHookean' is now 'quadratic' "
            "(Psi_vol = (J - 1)^2/d0, paper eq. 2; d0 = 0: incompressible)"
        );
    }
    else
    {
        throw SolidError
        (
            SolidError::Kind::parameter,
            ctx + ": unknown volumetric law '" + par.volumetric
          + "'; valid: quadratic mieGruneisen"
        );
    }
    return std::unique_ptr<Material>
    (
        new Material(par.name, par.rho0, std::move(iso), std::move(vol))
    );
}

