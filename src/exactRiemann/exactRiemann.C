/*---------------------------------------------------------------------------*\
Application
    exactRiemann

Description
    Samples the exact solution of a one-dimensional Riemann problem with a
    run-time selected equation of state at time t on n points of
    [xMin, xMax] and prints the columns x rho u p e (SI units, header line
    with the units; the star state and the waves as '#' comment lines).
    Input: an optional case file of "key value;" entries followed by
    key=value arguments, see riemann::exactRiemannInput for the entries.
    Exit status 1 on invalid input or a solution outside the law.

Usage
    \verbatim
        exactRiemann [caseFile] [key=value ...]
        exactRiemann water.case t=2e-5 n=401
    \endverbatim
\*---------------------------------------------------------------------------*/

#include "anyExactRiemannSolver.H"
#include "exactRiemannInput.H"
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <set>

#include "fileKind.H"

namespace
{

void usage(std::ostream& os)
{
    os  << "Usage: exactRiemann [caseFile] [key=value ...]\n"
        << "  entries: law (mieGruneisen|stiffenedGas|idealGas), the law's "
        << "coefficients,\n"
        << "  rhoL uL pL rhoR uR pR [kg/m^3, m/s, Pa], x0 [m], t [s], "
        << "xMin xMax [m], n [-]\n";
}

void printWave(const char* side, const riemann::wave& w)
{
    std::printf
    (
        "# %s wave: %s, head %.10e m/s, tail %.10e m/s\n",
        side, riemann::waveTypeName(w.type), w.headSpeed, w.tailSpeed
    );
}

} // namespace


int main(int argc, char* argv[])
{
    // a write beyond `ulimit -f` fails (EFBIG, reported below) rather than
    // ending the process by SIGXFSZ without a word (adv52 p08)
    std::signal(SIGXFSZ, SIG_IGN);
    if (argc < 2)
    {
        usage(std::cerr);
        return 1;
    }
    if (!std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "-help"))
    {
        usage(std::cout);
        return 0;
    }

    try
    {
        riemann::exactRiemannInput::entryTable entries;
        std::set<std::string> argumentKeys;
        for (int i = 1; i < argc; ++i)
        {
            if (std::strchr(argv[i], '='))
            {
                riemann::exactRiemannInput::readArgument
                (
                    argv[i], entries, argumentKeys
                );
            }
            else if (i == 1)
            {
                // Not a regular file (a FIFO, /dev/zero: read without
                // end, adv52 p10) or beyond a case file's size: refused
                // before it is opened (src/foamTools/fileKind.H)
                const std::string refusal
                (
                    fileKind::readRefusal
                    (
                        argv[i], fileKind::dictionaryLimit, "case file"
                    )
                );
                if (!refusal.empty())
                {
                    std::cerr << "exactRiemann: error: case file "
                        << refusal << "\n";
                    return 1;
                }
                std::ifstream file(argv[i]);
                if (!file)
                {
                    std::cerr << "exactRiemann: cannot open case file '"
                        << argv[i] << "'\n";
                    return 1;
                }
                riemann::exactRiemannInput::read(file, argv[i], entries);
            }
            else
            {
                std::cerr << "exactRiemann: argument '" << argv[i]
                    << "' is not of the form key=value\n";
                usage(std::cerr);
                return 1;
            }
        }

        const riemann::exactRiemannInput rc(entries);
        const riemann::anyExactRiemannSolver solver
        (
            rc.law(), rc.left(), rc.right()
        );
        const auto& s = solver.star();
        const auto x = rc.points();
        const auto states = solver.sample(x, rc.t(), rc.x0());

        std::printf
        (
            "# exactRiemann: law %s, t = %.10e s, x0 = %.10e m\n",
            riemann::eosName(rc.law()).c_str(), rc.t(), rc.x0()
        );
        std::printf
        (
            "# p* = %.10e Pa, u* = %.10e m/s, rho*L = %.10e kg/m^3, "
            "rho*R = %.10e kg/m^3 (%d Newton iterations)\n",
            s.p, s.u, s.rhoL, s.rhoR, s.iterations
        );
        printWave("left", solver.waves().left);
        printWave("right", solver.waves().right);
        std::printf
        (
            "# x [m]  rho [kg/m^3]  u [m/s]  p [Pa]  e [J/kg]\n"
        );
        for (std::size_t i = 0; i < x.size(); ++i)
        {
            const auto& q = states[i];
            std::printf
            (
                "%.10e %.10e %.10e %.10e %.10e\n",
                x[i], q.rho, q.u, q.p, q.e
            );
        }
    }
    catch (const std::exception& err)
    {
        std::cerr << "exactRiemann: " << err.what() << "\n";
        return 1;
    }
    // the output written whole (a full disk, `ulimit -f`: EFBIG)
    if (std::fflush(stdout) != 0 || std::ferror(stdout))
    {
        std::cerr << "exactRiemann: cannot write the output to the standard"
            " output: " << std::strerror(errno) << "\n";
        return 1;
    }
    return 0;
}
