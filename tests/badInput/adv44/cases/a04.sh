#!/bin/bash
# a04 (class 3, a03 with nProcs 2): overpressure (30e6 30.0000001e6), nProcs 2: the two points (one label, one folder) run AT ONCE in the same points/p3e+07_T2e-09/case: refused before, or the two runs in one case (one removes the other's copy), and what is reported?
. "$(dirname "$0")/../lib.sh"
study; setStudy overpressure "(30e6 30.0000001e6)"; setStudy nProcs 2; run 250 ./Allrun > ../log.s1 2>&1; echo "   rc above; first: $(grep -a -i -m8 'error\|refus\|done\|points\|FAIL\|lock\|in use' ../log.s1 | cut -c1-220 | tr '\n' '|')"
S=postProcessing/pulseStudy; echo "   points: $(ls $S/points | tr '\n' ' '); in it: $(ls $S/points/* | tr '\n' ' '); table rows: $(tail -n +2 $S/table.csv 2>/dev/null | grep -vc '^#')"
