#!/bin/bash
# CASETIMEOUT=600
# l16 (new, class 6: planeWave's own sizes - the 1D reference's cells and steps - which no pass pushed): on bd:
# (a) planeWave -dz 1e-12 (2e7 cells of the 20 um column), (b) -endTime 1e-3 (a millisecond of 1D time), (c) -maxCells
# 1e12, (d) -maxSteps 1e15, (e) -layered -dz 1e-11, (f) -radius 1e-300. Each under a 120 s KILL timeout and
# /usr/bin/time. Expected: refused before computing, naming the option and the limit, or done within its limits; a
# MemoryError traceback or a run to the timeout = CRASH / HANG.
. "$(dirname "$0")/../lib.sh"
bd
for o in "-dz 1e-12" "-endTime 1e-3" "-maxCells 1e12" "-maxSteps 1e15" "-layered -dz 1e-11" "-radius 1e-300"; do
  rm -rf postProcessing/planeWave; tryt 120 "planeWave $o" /usr/bin/time -f "maxRSS %M kB, %e s" planeWave -case . $o; echo "   tracebacks $(grep -a -c Traceback $W/try.log) | said: $(say 2 | cut -c1-250) | $(tail -1 $W/try.log | cut -c1-100)"; done
