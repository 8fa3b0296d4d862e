/*---------------------------------------------------------------------------*\
Application
    cellIndentationFoam

Description
    Quasi-static nanoindentation of the axisymmetric (or 3D) cell by a
    rigid sphere through a multi-rate loading table (Jerusalem & Dao 2012,
    sec. 2.2.1 and 3; Table 1). Solid only: the cell of
    constant/solidProperties (Foam::solidInput; the paper's materials:
    etc/caseDicts/cellMaterials/<set>), the sphere, its loading
    table and stepping of constant/indenterProperties and the output
    entries of system/controlDict (Foam::indentationInput: entries, ranges,
    restart), driven by solid::IndentationDriver.

    Outputs (postProcessing/indentation/):
        force.dat   time [s], depth [m], force [N], contact radius [m],
                    max penetration [m], stage (header line)
        peaks.dat   the cycle maxima and F at the end of B and E
        solid.h5/.xmf   fields at the peaks, the stage ends B and E and
                    every fieldWriteInterval; ParaView opens solid.xmf
        materials.dat   the material of every region as built (17 digits)
        restart.h5  the last checkpoint

Usage
    cellIndentationFoam [-case dir]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "inputChecks.H"
#include "Time.H"
#include "IOdictionary.H"

#include "indentationInput.H"
#include "solidInput.H"

#include "SolidError.H"
#include "caseLock.H"
#include "inputChecks.H"
#include "resultGuard.H"

#include <chrono>
#include <ctime>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Quasi-static indentation of the cell by a rigid sphere through a "
        "multi-rate loading table (solid only)"
    );
    argList::noParallel();
    foamTools::resultGuard::addOption();
    // setRootCase.H with checkCasePath before OpenFOAM checks the case
    #include "setRootCaseChecked.H"
    foamTools::checkOptions(args);     // no nan, inf or 1e999 in options
    // A number beyond a double's range is a sigFpe inside OpenFOAM's
    // tokenizer: every file of the case the run reads is scanned first,
    // naming the file, the line and the entry
    foamTools::checkNumbers(args);
    // controlDict: OpenFOAM's keywords and ours, each given once
    foamTools::checkControlDict
    (
        args, {"fieldWriteInterval", "checkpointInterval", "maxSteps"}
    );
    const foamTools::caseLock lock(args);    // one run per case
    #include "createTime.H"
    // No function objects run here: one in controlDict is an error
    foamTools::checkFunctionObjects(runTime, runTime, true);
    #include "createFields.H"

    // Wall and CPU time: on a shared machine the CPU time of this process
    // is the one-core cost
    const auto wall0 = std::chrono::steady_clock::now();
    const std::clock_t cpu0 = std::clock();
    try
    {
        driver->run();
    }
    catch (const solid::SolidError& err)
    {
        // A step that does not converge names no input by itself: the
        // inputs that decide it (no support along the axis, a material far
        // too soft, steps far too small were each reported as "line
        // search failed" alone; issue 19)
        FatalErrorInFunction
            << "at t = " << model.time << " s: " << err.what();
        if (err.kind() == solid::SolidError::Kind::notConverged)
        {
            FatalError
                << nl << "    The static solve of the cell did not converge."
                << " It depends on these inputs: constant/solidProperties,"
                << " entries 'materials' (C10, d0 and the Maxwell branches"
                << " of each region) and 'fixed' (the supports);"
                << " constant/indenterProperties, entries 'maxDeltaT' = "
                << indenter.settings().maxDeltaT << " s, 'holdDeltaT0' = "
                << indenter.settings().holdDeltaT0 << " s, "
                << "'maxDepthIncrement' = "
                << indenter.settings().maxDepthIncrement << " m, 'tolerance'"
                << " and 'penaltyFactor' (the contact), and the rows of"
                << " 'protocol'";
            // The first step from rest moving the indenter by less than
            // about 1e-10 m: its residual stops at round-off above the
            // tolerance, relative to the step's own tiny force (issue 19,
            // adv35 s13, s05: maxDeltaT 1e-6 s and 1e-5 s, inside their
            // range, refused naming seven inputs but not the cause).
            // Measured on the average cell's meshes (cells of 7.9 um):
            // first steps of 3e-13 m and 3e-12 m fail, 3e-11 m and 3e-10 m
            // run (docs/reliability.md, adv35 rows)
            const auto& rows = indenter.protocol()->rows();
            const auto& set = indenter.settings();
            const scalar minDepth = 1e-10;
            if (model.time == 0 && !rows.empty() && rows[0].motion != "hold"
             && rows[0].rate > 0)
            {
                const scalar rate = rows[0].rate;
                const scalar dt0 =
                    std::min(set.maxDeltaT, set.maxDepthIncrement/rate);
                if (rate*dt0 < minDepth)
                {
                    FatalError
                        << nl << "    The cause is the first step from rest,"
                        << " of " << dt0 << " s: at the first row's rate, "
                        << rate << " m/s, it moves the indenter "
                        << rate*dt0 << " m, so little that the residual of"
                        << " the step stops at round-off above its tolerance"
                        << " (1e-9 of the step's own force). The valid range"
                        << " for this protocol: entry 'maxDeltaT' >= "
                        << minDepth/rate << " s and entry 'maxDepthIncrement'"
                        << " >= " << minDepth << " m (a first step of at"
                        << " least " << minDepth << " m; constant/"
                        << "indenterProperties)";
                }
            }
        }
        FatalError << exit(FatalError);
    }
    catch (const std::exception& err)
    {
        // solid::SolidError, and any standard exception (a std::
        // filesystem error) as a FatalError, never std::terminate
        FatalErrorInFunction
            << "at t = " << model.time << " s: " << err.what()
            << exit(FatalError);
    }
    const double wall = std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - wall0
    ).count();
    const double cpu = double(std::clock() - cpu0)/CLOCKS_PER_SEC;

    const solid::IndentationCounters& n = driver->counters();
    Info<< nl << "Protocol done: " << n.steps << " steps, " << n.iterations
        << " Newton iterations, " << n.augmentations << " augmentations, "
        << n.cuts << " step cuts, " << contact->penaltyRaises()
        << " penalty raises, wall time " << wall << " s, CPU time "
        << cpu << " s (assembly " << n.assemblySeconds
        << " s, factorise + solve " << n.solveSeconds << " s)" << nl
        << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
