#!/bin/bash
# b09 (class 3, two sweepCase of the same -name started at once on one case): both "sweepCase -values '0.1e-6 0.05e-6'" started together: one refused naming the other (run folders or the report in use), the other completes; one report, of one sweep; no run folder of one removed by the other?
. "$(dirname "$0")/../lib.sh"
ind
for k in 1 2; do sweepCase -case . -entry constant/indenterProperties/maxDepthIncrement -values "0.1e-6 0.05e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force" > ../log.s$k 2>&1 & eval p$k=$!; done
wait $p1; r1=$?; wait $p2; r2=$?; echo "   rc: $r1 $r2"; for k in 1 2; do echo "   s$k: $(grep -a -i -m2 'error\|refus\|use' ../log.s$k | cut -c1-220 | tr '\n' '|') $(grep -a -c '^|' ../log.s$k) table lines"; done
echo "   report: $(ls postProcessing/sweep 2>/dev/null | tr '\n' ' ') rows $(grep -c '^|' postProcessing/sweep/*.md 2>/dev/null); left: $(ls -d $W/ind.* 2>/dev/null | xargs -n1 basename | tr '\n' ' ')"
