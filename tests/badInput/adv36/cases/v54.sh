#!/bin/bash
# v54: hold step: holdGrowth 1e300, 0.5, 11, nan, 1e400 (outside or at the edge of the range)
. "$(dirname "$0")/../lib.sh"
ind; for g in 1e300 0.5 11 nan 1e400; do setd constant/indenterProperties holdGrowth $g 2>/dev/null || sed -i "s/^holdGrowth .*/holdGrowth $g;/" constant/indenterProperties; cellIndentationFoam > log.run 2>&1; echo "holdGrowth $g rc=$? $(grep -a -A1 FATAL log.run | tail -1 | cut -c1-200)"; done
