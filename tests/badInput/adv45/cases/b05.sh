#!/bin/bash
# b05 (class 4, sweepCase with unicode and a space in the case path): (a) $W/célula_ü/ind: the sweep runs (OpenFOAM takes UTF-8 names) or is refused naming the path; (b) "$W/my case/ind": refused before anything is copied, naming the path (OpenFOAM cannot hold a space), nothing left beside it?
. "$(dirname "$0")/../lib.sh"
ind; cd $W; mkdir -p "célula_ü" "my case"; cp -r ind "célula_ü/ind"; cp -r ind "my case/ind"
tryf "(a) unicode" sweepCase -case "$W/célula_ü/ind" -entry constant/indenterProperties/maxDepthIncrement -values "0.1e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force"; grep -a '^|' $W/try.log | head -3; echo "   célula_ü/: $(ls -a "célula_ü" | tr '\n' ' ')"
tryf "(b) space" sweepCase -case "$W/my case/ind" -entry constant/indenterProperties/maxDepthIncrement -values "0.1e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force"; echo "   my case/: $(ls -a "my case" | tr '\n' ' '); its ind: $(ls -a "my case/ind" | tr '\n' ' ')"
