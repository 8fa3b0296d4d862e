#!/bin/bash
# g49 (class 4/6, planeWave's ranges at their edges) on the finished preview (bd, -Z 20e-6): -Z 0, -Z -1e-6, -dz 0, -dz 1e-3 (coarser than the column), -Z 1e308, -dz 4.9e-324, -endTime 0, -endTime -1e-9, -maxSteps 0, -maxSteps 1.5, -maxCells -1, -radius 0, -inflow 20e-6 (= -Z), -inflow 30e-6 (above -Z), -dz 1e-15 -maxCells 1e15 (2e10 cells), -endTime 1e-3 -maxSteps 1e15: each refused before computing, naming the option, the value and the range (or the count against its limit); no traceback, no memory exhaustion (maxRSS printed).
. "$(dirname "$0")/../lib.sh"
bd
for o in "-Z 0" "-Z -1e-6" "-dz 0" "-dz 1e-3" "-Z 1e308" "-dz 4.9e-324" "-endTime 0" "-endTime -1e-9" "-maxSteps 0" "-maxSteps 1.5" "-maxCells -1" "-radius 0" "-inflow 20e-6" "-inflow 30e-6" "-dz 1e-15 -maxCells 1e15" "-endTime 1e-3 -maxSteps 1e15"; do tryt 90 "$o" /usr/bin/time -f "maxRSS %M kB" planeWave -case . $o; grep -a maxRSS $W/try.log | sed 's/^/   /'; done
