// libFuzzer harness: the indentation loading table (solid::
// IndentationProtocol). The input is read as table text, one row a line
// "stage motion rate amount" (the rows cellIndentationFoam passes on);
// the protocol must either be built or throw SolidError, and a built one
// must answer depth/rate/rowAt/peaks/stageEnd/withFirstRowAmount for any
// time without a crash or undefined behaviour.
#include "IndentationProtocol.H"
#include "SolidError.H"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    std::istringstream is(std::string(reinterpret_cast<const char*>(data),
                                      size));
    std::vector<solid::ProtocolRow> rows;
    std::string line;
    while (std::getline(is, line) && rows.size() < 64)
    {
        std::istringstream ls(line);
        solid::ProtocolRow r;
        if (ls >> r.stage >> r.motion >> r.rate >> r.amount)
        {
            rows.push_back(r);
        }
    }
    try
    {
        const solid::IndentationProtocol p(rows);
        const double T = p.endTime();
        for (double f : {-1.0, 0.0, 0.25, 0.5, 0.999, 1.0, 2.0})
        {
            const double t = std::isfinite(T) ? f*T : f;
            const double d = p.depth(t);
            const double v = p.rate(t);
            const int i = p.rowAt(t);
            if (i < 0 || i >= int(p.rows().size()) || !std::isfinite(d)
             || !std::isfinite(v))
            {
                __builtin_trap();
            }
        }
        for (const auto& peak : p.peaks())
        {
            if (!std::isfinite(peak.time) || !std::isfinite(peak.depth))
            {
                __builtin_trap();
            }
        }
        p.stageEnd(p.rows().front().stage);
        p.withFirstRowAmount(p.rows().front().amount*0.5);
    }
    catch (const solid::SolidError&)
    {
    }
    return 0;
}
