#!/bin/bash
# x79: blast finished to 2 ns; the user runs OpenFOAM post-processing that writes INTO the latest time (postProcess -func writeCellCentres -latestTime: C, Cx, Cy, Cz added; foamToVTK beside): the restart to 3 ns accepted (the run's files unchanged), or refused for added files? said?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; postProcess -func writeCellCentres -latestTime > log.pp 2>&1 || tail -3 log.pp; ls 2e-09 | tr '\n' ' '; echo
try "restart after postProcess wrote into 2e-09" cellBlastFoam; echo "times: $(ls -d [1-9]* | tr '\n' ' ')"
