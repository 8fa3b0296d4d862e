#!/bin/bash
# i57 (class 4/6, planeWave's options at their edges and together, on bd): -Z 0, -Z -20e-6, -dz 0, -dz 1e-301, -endTime 0,
# -inflow 30e-6 with -Z 20e-6 (the inflow above the column's top: valid alone), -maxSteps 1 (below the estimate: the estimate
# named), -maxSteps 1e6 with -dz 1e-9 (the estimate above it), -maxCells 0, -radius -1: each refused within 60 s naming the
# option, value and range/estimate, exit non-zero, nothing written (-check/-inflow outputs absent).
. "$(dirname "$0")/../lib.sh"
bd; sums > ../s0
for a in "-Z 0" "-Z -20e-6" "-dz 0" "-dz 1e-301" "-endTime 0" "-inflow 30e-6 -Z 20e-6" "-maxSteps 1" "-dz 1e-9 -maxSteps 1e6" "-maxCells 0" "-radius -1"; do
  tryt 60 "planeWave $a" planeWave $a; echo "   changed: $(changed ../s0)"; done
