#!/bin/bash
# a32 (class 2+4, calibrateCell -work pointing at folders that hold the user's things): the calibration tutorial; -work (a) . (the case itself), (b) constant, (c) postProcessing (holding the user's notes.md), (d) $W/mine (the user's folder with a file), (e) a file: each refused before anything runs, nothing removed?
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/mine; echo "a32 mine" > $W/mine/data.txt; cal; sed -i 's/^maxIterations .*/maxIterations        1;/' system/calibrationDict; mkdir -p postProcessing; echo "# a32 pp notes" > postProcessing/notes.md; echo "a32 a file" > ../afile; sums > ../s
for w in . constant postProcessing $W/mine ../afile; do tryf "-work $w" calibrateCell -case . -nProcs 1 -work $w; echo "   changed: $(changed ../s | cut -c1-200)"; done; where "a32 mine" "# a32 pp notes" "a32 a file"
