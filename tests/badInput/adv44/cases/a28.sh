#!/bin/bash
# a28 (class 5, pulseStudy's record copied from ANOTHER study of the same point): two studies of the same one-point grid (30 MPa, 2 ns), the second with other baseOptions (-cell 0.4e-6 instead of 0.5e-6); the first's points/<label>/result.json copied over the second's (the user merging studies); ./Allrun in the second: refused naming the record (its inputs differ), or the first's result tabulated as the second's?
. "$(dirname "$0")/../lib.sh"
study; run 250 ./Allrun > ../log.s1 2>&1; echo "   study 1: $(grep -a -i -m2 'error\|done' ../log.s1 | cut -c1-140 | tr '\n' '|')"; cd $W; mv study study1
study; sed -i 's/-cell 0.5e-6/-cell 0.4e-6/' system/pulseStudyDict; grep -a '^baseOptions' system/pulseStudyDict | tr -s ' '; run 250 ./Allrun > ../log.s2 2>&1; echo "   study 2: $(grep -a -i -m2 'error\|done' ../log.s2 | cut -c1-140 | tr '\n' '|')"
L=postProcessing/pulseStudy/points/p3e+07_T2e-09; cp postProcessing/pulseStudy/table.csv ../t2; cp $W/study1/$L/result.json $L/result.json
run 250 ./Allrun > ../log.s3 2>&1; echo "   study 2 again: $(grep -a -i -m3 'error\|refus\|differ\|not run\|done' ../log.s3 | cut -c1-260 | tr '\n' '|')"; echo "   table.csv $(cmp -s postProcessing/pulseStudy/table.csv ../t2 && echo unchanged || echo CHANGED)"
