#!/bin/bash
# d68 (class 3, two sweepCase at once on the same indentation case with the same -name and -keep): one refused naming the other, or both complete with separate run folders and one report that matches its runs; never a run folder used by both or a report of mixed rows.
. "$(dirname "$0")/../lib.sh"
ind; for k in 1 2; do sweepCase -case . -entry constant/indenterProperties/maxDepthIncrement -values "0.1e-6 0.05e-6" -name same -keep -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force" > ../s$k 2>&1 & eval p$k=\$!; sleep 0.3; done; wait $p1; r1=$?; wait $p2; r2=$?
echo "first rc=$r1: $(grep -a -m2 -i "error\|refus\|running\|exists" ../s1 | cut -c1-200 | tr "\n" " ")"; echo "second rc=$r2: $(grep -a -m2 -i "error\|refus\|running\|exists" ../s2 | cut -c1-200 | tr "\n" " ")"
ls $W; ls postProcessing/sweep 2>&1; cat postProcessing/sweep/same.md 2>/dev/null | grep "^|" | head -5
