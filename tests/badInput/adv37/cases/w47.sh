#!/bin/bash
# w47: planeWave option values at their edges: -dz 0, -dz -1e-9, -dz nan, -endTime 0, -endTime -1e-9, -maxCells 0, -maxSteps 0.5, -Z inf
. "$(dirname "$0")/../lib.sh"
blastDone; for o in "-dz 0" "-dz -1e-9" "-dz nan" "-endTime 0" "-endTime -1e-9" "-maxCells 0" "-maxSteps 0.5" "-Z inf"; do try "$o" planeWave -case . $o; done
