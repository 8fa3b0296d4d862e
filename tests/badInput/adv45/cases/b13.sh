#!/bin/bash
# b13 (class 4, pulseStudyDict grid given through a macro): `amp 30e6; overpressure ($amp);` (OpenFOAM's $ substitution): refused naming the entry (not a number), or the point run with 30 MPa (its label p3e+07_..., its Allrun -amplitude 30e6)? Never a point of another amplitude or a label made from the text "$amp".
. "$(dirname "$0")/../lib.sh"
study; sed -i 's/^overpressure .*/amp             30e6;\noverpressure    ($amp);/' system/pulseStudyDict; grep -a -n 'amp' system/pulseStudyDict | tr '\n' ' '; echo
run 200 pulseStudy -case . -keep > ../log.s 2>&1; grep -a -m3 -i 'error\|refus\|done\|amp' ../log.s | cut -c1-220; echo "   points: $(ls postProcessing/pulseStudy/points 2>/dev/null | tr '\n' ' ')"
grep -a -h -o -- '-amplitude [^ ]*' postProcessing/pulseStudy/points/*/case/log.* 2>/dev/null | sort -u | head -3
