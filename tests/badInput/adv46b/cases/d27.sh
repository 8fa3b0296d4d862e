#!/bin/bash
# d27 (class 4, sweepCase -output naming a column the file does not have, and a file that does not exist): refused before running, or the run folder kept and the error names file and column.
. "$(dirname "$0")/../lib.sh"
ind; tryt 200 "(a) column nonexistent" sweepCase -case . -entry constant/indenterProperties/maxDepthIncrement -values "0.1e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:nosuchcolumn"; ls $W
tryt 200 "(b) file nonexistent" sweepCase -case . -entry constant/indenterProperties/maxDepthIncrement -values "0.1e-6" -name b -run cellIndentationFoam -output "F=postProcessing/indentation/nosuch.dat:-1:force"; ls $W; ls postProcessing/sweep 2>&1
