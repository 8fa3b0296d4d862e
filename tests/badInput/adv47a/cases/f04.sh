#!/bin/bash
# f04 (class 5+1, adv46b d65 varied: another state file of the restart time removed; the finished preview, startFrom
# latestTime, endTime 3e-9): (a) 2e-09/uniform/fsiState removed, (b) 2e-09/uniform/solidState removed, (c) uniform/ whole
# removed and Gamma0 0.1 -> 0.2, (d) inputDigests replaced by 1e-09's (a valid record of the same run, another time) and
# Gamma0 0.2, (e) inputDigests emptied (0 bytes) and Gamma0 0.2, (f) functionObjects/functionObjectProperties removed
# (OpenFOAM's own state). (a)-(e) refused naming the file (or 2e-09 moved aside as incomplete); never a restart from 2e-09
# with Gamma0 0.2 or without its state; (f) refused, or a restart whose results are the plain restart's. Cut at 90 s each.
. "$(dirname "$0")/../lib.sh"
bd; rs; cp -a . ../keep; G() { sed -i "s/Gamma0  0.1; /Gamma0  0.2; /" constant/thermophysicalProperties; echo "   Gamma0 0.2: $(grep -c 'Gamma0  0.2' constant/thermophysicalProperties)"; }
one() { tryt 90 "$1" cellBlastFoam; echo "   $(grep -a -m1 'Restarting from' $W/try.log | cut -c1-140) | times: $(ls -d [0-9]* *incomplete* 2>/dev/null | tr '\n' ' ')"; cd $W; rm -rf blast; cp -a keep blast; cd blast; }
rm 2e-09/uniform/fsiState; one "(a) fsiState removed"
rm 2e-09/uniform/solidState; one "(b) solidState removed"
rm -r 2e-09/uniform; G; one "(c) 2e-09/uniform removed, Gamma0 0.2"
cp 1e-09/uniform/inputDigests 2e-09/uniform/inputDigests; G; one "(d) inputDigests of 1e-09, Gamma0 0.2"
: > 2e-09/uniform/inputDigests; G; one "(e) inputDigests emptied, Gamma0 0.2"
rm 2e-09/uniform/functionObjects/functionObjectProperties; one "(f) functionObjectProperties removed"
