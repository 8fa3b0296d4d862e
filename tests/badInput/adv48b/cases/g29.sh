#!/bin/bash
# g29 (class 4/6, sweepCase -maxRuns at its edges) on the smoke indentation (idn, finished): -maxRuns 0, -1, 1.5, 1e3, nan, 0x10, 99999999999999999999, and 3 values with -maxRuns 2, and 1001 values without -maxRuns (default 1000): each refused before anything is copied, naming -maxRuns, the count and the range; nothing new beside the case.
. "$(dirname "$0")/../lib.sh"
idn; cd ..; ls > ../l0; O="-case ind -entry constant/indenterProperties/holdGrowth -output F=postProcessing/indentation/peaks.dat:max:force -run cellIndentationFoam"
for m in 0 -1 1.5 1e3 nan 0x10 99999999999999999999; do tryt 60 "-maxRuns $m" sweepCase $O -values "1.5 1.6" -maxRuns $m; killIn $W; done
tryt 60 "3 values, -maxRuns 2" sweepCase $O -values "1.5 1.6 1.7" -maxRuns 2
v=$(seq 1001 | awk '{printf "%s ", 1.5 + $1 * 1e-4}'); tryt 60 "1001 values" sweepCase $O -values "$v"; ls > ../l1; diff ../l0 ../l1 && echo "   nothing new beside the case"
