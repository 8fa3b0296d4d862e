#!/bin/bash
# z25: pulseStudy with baseOptions asking for a resource beyond the limits (-cell 1e-9: cellMesh's estimate) and with an option of a bad value for the Allrun (-writeInterval 0): refused before or at the point, naming the option/point, with no table and quickly (not a point run to its end)?
. "$(dirname "$0")/../lib.sh"
study; sed -i 's/^baseOptions .*/baseOptions     (-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 1e-9 -Z 20e-6 -endTime 2e-9);/' system/pulseStudyDict
run 200 ./Allrun > ../log.s1 2>&1; echo "(a) -cell 1e-9: rc=$? $(grep -a -i -m3 'error\|refus\|fail\|elements' ../log.s1 | cut -c1-220 | tr '\n' '|')"; ls postProcessing/pulseStudy 2>/dev/null | tr '\n' ' '; echo
./Allclean > /dev/null 2>&1; rm -rf postProcessing; sed -i 's/-cell 1e-9/-cell 0.5e-6 -writeInterval 0/' system/pulseStudyDict
run 200 ./Allrun > ../log.s2 2>&1; echo "(b) -writeInterval 0: rc=$? $(grep -a -i -m3 'error\|refus\|fail' ../log.s2 | cut -c1-220 | tr '\n' '|')"
