#!/bin/bash
# w104: sweepCase SIGKILLed during its first run, then the same command again: refused naming the leftover run folder, or a table mixing runs?
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.02e-6/' constant/indenterProperties; a=(-case . -entry constant/indenterProperties/radius -values "22e-6 21e-6" -run cellIndentationFoam -name k -nProcs 1 -output "F=postProcessing/indentation/peaks.dat:-1:force")
sweepCase "${a[@]}" > log.s1 2>&1 & p=$!; sleep 3; kill -KILL $p; wait $p 2>/dev/null; echo "killed; still running: $(inDir $W)"; ls .. | tr '\n' ' '; echo; sleep 2
run 200 sweepCase "${a[@]}" > log.s2 2>&1; tail -4 log.s2 | cut -c1-250
