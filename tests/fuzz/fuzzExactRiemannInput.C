// libFuzzer harness: the exactRiemann case reader
// (riemann::exactRiemannInput: "key value" text, comments, ';'), then the exact solver on the accepted
// case, sampled at a few points. Bad input must be reported by an
// exception (exactRiemann prints it and exits 1); no crash, hang, or
// undefined behaviour.
#include "anyExactRiemannSolver.H"
#include "exactRiemannInput.H"

#include <cstdint>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    std::istringstream is(std::string(reinterpret_cast<const char*>(data),
                                      size));
    try
    {
        riemann::exactRiemannInput::entryTable entries;
        riemann::exactRiemannInput::read(is, "fuzz", entries);
        const riemann::exactRiemannInput rc(entries);
        const riemann::anyExactRiemannSolver solver
        (
            rc.law(), rc.left(), rc.right()
        );
        for (double xi : {-1e5, -1.0, 0.0, 1.0, 1e5})
        {
            solver.sample(xi);
        }
        const std::vector<double> x{rc.x0() - 1e-3, rc.x0(), rc.x0() + 1e-3};
        solver.sample(x, rc.t(), rc.x0());
    }
    catch (const std::exception&)
    {
    }
    return 0;
}
