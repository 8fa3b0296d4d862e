#!/bin/bash
# d42 (class 4, sweepCase -values odd): "nan", "1e400", "0x1p-23", "-0", "1e-7 1e-7" (twice the same), "1e-7,2e-7", "" (empty): each refused naming -values and the value before anything runs; the duplicated value refused or run once with a note.
. "$(dirname "$0")/../lib.sh"
ind; for v in "nan" "1e400" "0x1p-23" "-0" "1e-7 1e-7" "1e-7,2e-7" ""; do tryt 100 "[$v]" sweepCase -case . -entry constant/indenterProperties/maxDepthIncrement -values "$v" -name "x$RANDOM" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force"; grep -a "^|" $W/try.log | head -4; done; ls $W
