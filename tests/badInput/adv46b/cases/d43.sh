#!/bin/bash
# d43 (class 4, planeWave options odd on the preview, 40 s each): -Z -0, -endTime 4.9e-324, -dz 0x1p-20, -dz " 0.25e-6", -maxSteps 1e308, -radius nan, -maxCells 0: each refused naming the option and range, nothing written.
. "$(dirname "$0")/../lib.sh"
blast; sums > ../s0; for o in "-Z -0" "-endTime 4.9e-324" "-dz 0x1p-20" "-maxSteps 1e308" "-radius nan" "-maxCells 0"; do tryt 40 "[$o]" planeWave $o; done; tryt 40 "[-dz \" 0.25e-6\"]" planeWave -dz " 0.25e-6"; nochange ../s0; ls
