#!/bin/bash
# d72 (class 4, sweepCase -nProcs odd: 0, -1, 2.5, 1e308, 0x2, "" (empty)): each refused naming -nProcs and its range before anything is copied; nothing left beside the case.
. "$(dirname "$0")/../lib.sh"
ind; for n in 0 -1 2.5 1e308 0x2 ""; do tryt 60 "[-nProcs $n]" sweepCase -case . -entry constant/indenterProperties/maxDepthIncrement -values "0.1e-6" -nProcs "$n" -name "n$RANDOM" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force"; done; ls $W
