#!/bin/bash
# b06 (class 4, sweepCase -values with odd numbers): maxDepthIncrement swept over each of 1e308, 1e-400, -0, 0x1p-24 (hex), 4.9e-324 (a denormal), 1e400, "0.1e-6 0.1e-6" (the same value twice), "1e-7 0.1e-6" (equal written two ways): each refused before any run naming the value (and a range), or run and refused by the solver naming the entry; never a table row of a value the run did not read; the case unchanged, nothing left?
. "$(dirname "$0")/../lib.sh"
ind; md5sum constant/* system/* > ../m; i=0
for v in 1e308 1e-400 -0 0x1p-24 4.9e-324 1e400 "0.1e-6 0.1e-6" "1e-7 0.1e-6"; do i=$((i+1)); tryf "'$v'" sweepCase -case . -entry constant/indenterProperties/maxDepthIncrement -values "$v" -name v$i -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force"; grep -a '^|' $W/try.log | sed -n 3,4p; done
echo "   the case: $(md5sum -c ../m 2>&1 | awk '{print $2}' | sort | uniq -c | tr '\n' ' '); reports: $(ls postProcessing/sweep 2>/dev/null | tr '\n' ' '); left: $(ls -d $W/ind.* 2>/dev/null | xargs -n1 basename 2>/dev/null | tr '\n' ' ')"
