#include "IndentationProtocol.H"
#include "SolidError.H"
#include "physicalBounds.H"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{

//- A number as the messages print it (1e-306, not 0.000000)
std::string num(double x)
{
    std::ostringstream os;
    os << x;
    return os.str();
}

} // namespace

solid::IndentationProtocol::IndentationProtocol(std::vector<ProtocolRow> rows)
:
    rows_(std::move(rows))
{
    if (rows_.empty())
    {
        throw SolidError
        (
            SolidError::Kind::parameter, "indentation protocol: no rows"
        );
    }
    double t = 0, d = 0;
    for (std::size_t i = 0; i < rows_.size(); ++i)
    {
        const ProtocolRow& r = rows_[i];
        const std::string ctx = "indentation protocol row "
            + std::to_string(i + 1) + " (stage '" + r.stage + "', "
            + r.motion + ")";
        double dt = 0, dd = 0;
        if (r.motion == "load" || r.motion == "unload")
        {
            // Finite bounds (physicalBounds.H): a rate of 1e300 m/s gave a
            // row shorter than the time resolution, a duration of 1e300 s
            // a floating-point exception (issue 19)
            checkParameter
            (
                ctx, "rate", r.rate, 0, physicalBounds::velocityMax, "m/s"
            );
            checkParameter
            (
                ctx, "amount", r.amount, 0, physicalBounds::depthMax, "m",
                false
            );
            dt = r.amount/r.rate;
            dd = r.motion == "load" ? r.amount : -r.amount;
        }
        else if (r.motion == "hold")
        {
            checkParameter
            (
                ctx, "amount", r.amount, 0, physicalBounds::timeMax, "s"
            );
            if (r.rate != 0)
            {
                throw SolidError
                (
                    SolidError::Kind::parameter,
                    ctx + ": a hold has rate 0, not " + std::to_string(r.rate)
                  + " m/s"
                );
            }
            dt = r.amount;
        }
        else
        {
            throw SolidError
            (
                SolidError::Kind::parameter,
                ctx + ": unknown motion '" + r.motion
              + "' (valid: load, unload, hold)"
            );
        }
        if (d + dd < -1e-12*std::abs(r.amount))
        {
            throw SolidError
            (
                SolidError::Kind::parameter,
                ctx + ": unloads to depth " + std::to_string(d + dd)
              + " m, above the undeformed surface (depth must stay >= 0)"
            );
        }
        if (!std::isfinite(t + dt) || !(t + dt < physicalBounds::timeMax))
        {
            throw SolidError
            (
                SolidError::Kind::parameter,
                ctx + ": the protocol ends at " + num(t + dt)
              + " s (this row lasts amount/rate = " + num(dt)
              + " s); the table must end before "
              + num(physicalBounds::timeMax) + " s"
            );
        }
        if (!(t + dt > t*(1 + 1e-9)))
        {
            throw SolidError
            (
                SolidError::Kind::parameter,
                ctx + ": the row lasts amount/rate = " + num(dt)
              + " s, below the time resolution at its start t = "
              + num(t) + " s (1e-9 t); give a smaller rate"
                " (m/s) or a larger amount"
            );
        }
        t0_.push_back(t);
        d0_.push_back(d);
        t += dt;
        d = std::max(0.0, d + dd);
        t1_.push_back(t);
        d1_.push_back(d);
    }
}


std::vector<solid::ProtocolRow> solid::IndentationProtocol::paperRows
(
    double delta0
)
{
    const double um = 1e-6;
    std::vector<ProtocolRow> r;
    r.push_back({"A", "load", 0.3*um, delta0});
    r.push_back({"B", "hold", 0, 15});
    const char* stage[] = {"C1", "C2", "C3"};
    const double rate[] = {10*um, 1*um, 0.1*um};
    for (int c = 0; c < 3; ++c)
    {
        for (int k = 0; k < 3; ++k)
        {
            r.push_back({stage[c], "load", rate[c], 2*um});
            r.push_back({stage[c], "unload", rate[c], 2*um});
        }
    }
    r.push_back({"D", "load", 10*um, 2*um});
    r.push_back({"E", "hold", 0, 120});
    return r;
}


solid::IndentationProtocol solid::IndentationProtocol::withFirstRowAmount
(
    double amount
) const
{
    std::vector<ProtocolRow> r = rows_;
    r[0].amount = amount;
    return IndentationProtocol(r);
}


int solid::IndentationProtocol::rowAt(double t) const
{
    const int n = int(rows_.size());
    for (int i = 0; i < n; ++i)
    {
        if (t <= t1_[i]) return i;
    }
    return n - 1;
}


double solid::IndentationProtocol::depth(double t) const
{
    if (t <= 0) return 0;
    if (t >= endTime()) return d1_.back();
    const int i = rowAt(t);
    const double s = (t - t0_[i])/(t1_[i] - t0_[i]);
    return d0_[i] + s*(d1_[i] - d0_[i]);
}


double solid::IndentationProtocol::rate(double t) const
{
    if (t < 0 || t > endTime()) return 0;
    const int i = rowAt(t);
    return (d1_[i] - d0_[i])/(t1_[i] - t0_[i]);
}


double solid::IndentationProtocol::stageEnd(const std::string& stage) const
{
    double t = -1;
    std::vector<std::string> names;
    for (std::size_t i = 0; i < rows_.size(); ++i)
    {
        if (rows_[i].stage == stage) t = t1_[i];
        if (std::find(names.begin(), names.end(), rows_[i].stage)
            == names.end())
        {
            names.push_back(rows_[i].stage);
        }
    }
    if (t < 0)
    {
        std::string list;
        for (const auto& n : names) list += " " + n;
        throw SolidError
        (
            SolidError::Kind::parameter, "indentation protocol: unknown "
            "stage '" + stage + "' (stages:" + list + ")"
        );
    }
    return t;
}


std::vector<solid::ProtocolPeak> solid::IndentationProtocol::peaks() const
{
    static const char* roman[] =
        {"i", "ii", "iii", "iv", "v", "vi", "vii", "viii", "ix", "x"};
    std::vector<ProtocolPeak> p;
    std::string stage;
    int count = 0;
    for (std::size_t i = 0; i + 1 < rows_.size(); ++i)
    {
        if
        (
            rows_[i].motion == "load" && rows_[i + 1].motion == "unload"
         && rows_[i + 1].stage == rows_[i].stage
        )
        {
            count = rows_[i].stage == stage ? count + 1 : 0;
            stage = rows_[i].stage;
            const std::string k =
                count < 10 ? roman[count] : std::to_string(count + 1);
            p.push_back({stage + "," + k, t1_[i], d1_[i]});
        }
    }
    return p;
}
