#!/bin/bash
# x48: sweepCase SIGKILLed during its first run (its base copy <case>.sweep_<name>_base and run folder left), then the same command: refused naming the left-over folders with what to do? the user's case unchanged? then the advice followed: the sweep completes?
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.02e-6/' constant/indenterProperties; sums > ../s0; a=(-case . -entry constant/indenterProperties/radius -values "22e-6 21e-6" -run cellIndentationFoam -name k -nProcs 1 -output "F=postProcessing/indentation/peaks.dat:-1:force")
sweepCase "${a[@]}" > ../log.s1 2>&1 & p=$!; sleep 3; kill -KILL $p; wait $p 2>/dev/null; sleep 0.5; echo "killed; left: $(ls .. | tr '\n' ' '); running: $(inDir $W)"; killIn $W; sleep 1
run 200 sweepCase "${a[@]}" > ../log.s2 2>&1; grep -a -v "^\s*$" ../log.s2 | tail -4 | cut -c1-350; sums > ../s1; cmp -s ../s0 ../s1 && echo "case unchanged" || diff ../s0 ../s1 | head
