#!/bin/bash
# b10 (class 4, sweepCase -output of a file the run does not write, a typo): -output "F=postProcessing/indentation/peak.dat:-1:1" (peak, not peaks): refused before any run, or the sweep fails after the runs naming the output and its file, exit non-zero, no table presented as a result; what is left said?
. "$(dirname "$0")/../lib.sh"
ind
tryf "-output of a missing file" sweepCase -case . -entry constant/indenterProperties/maxDepthIncrement -values "0.1e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peak.dat:-1:1"; grep -a '^|' $W/try.log | head -3
echo "   report: $(ls postProcessing/sweep 2>/dev/null | tr '\n' ' '); left: $(ls -d $W/ind.* 2>/dev/null | xargs -n1 basename | tr '\n' ' ')"
