#!/bin/bash
# The applied-pressure boundary, the rigid wall and the probes: a 50 MPa,
# 5 ns pulse applied on x = 0 of a water column (tutorial waterPulseWall).
# Asserts against the exact Hugoniot of water (C0 1450 m/s, s 1.99):
#  - plateau at mid-column 50 MPa within 2 %;
#  - arrival at x = 50 um (p > 25 MPa) at 0.05 ns (half the 0.1 ns ramp)
#    + 50 um / Us, Us = C0 + s up = 1515.65 m/s, i.e. 33.04 ns, within 1 %;
#  - reflection at the wall 104.43 MPa (exact collision of two 50 MPa
#    states, src/exactRiemann) within 2 %: the near-doubling with the nonlinear
#    law (2.09 x the incident pressure, not 2).
set -euo pipefail
dir=$(cd "$(dirname "$0")" && pwd)
out=$(bash "$dir/runTutorial.sh" "$dir/../../tutorials/verification/waterPulseWall")
line=$(echo "$out" | grep "plotProbes:")
echo "$line"
echo "$line" | awk '{
    mid = $4; arr = $11; wall = $15;
    ok = 1;
    if ((mid - 50)/50 > 0.02 || (50 - mid)/50 > 0.02) { print "FAIL plateau " mid " MPa"; ok = 0 }
    if ((arr - 33.04)/33.04 > 0.01 || (33.04 - arr)/33.04 > 0.01) { print "FAIL arrival " arr " ns"; ok = 0 }
    if ((wall - 104.43)/104.43 > 0.02 || (104.43 - wall)/104.43 > 0.02) { print "FAIL wall peak " wall " MPa"; ok = 0 }
    if (ok) print "pulseWall: plateau " mid " MPa, arrival " arr " ns, wall " wall " MPa: passed";
    exit !ok
}'
