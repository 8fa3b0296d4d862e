#!/bin/bash
# k31 (class 4, indenterProperties and the loading table at edges, units in the wrong dimension): the smoke indentation (ind: mesh, no results): radius 0, 1e300; tolerance 0; holdGrowth 1, 0.9999999999999999; maxDeltaT 0; penaltyFactor 0; a protocol row (A load 0.3e-6 [m] 0.3e-6) (a unit inside a row), (B hold 0 0) (a hold of 0 s), (A load 0 0.3e-6) (a load at rate 0), (A load 1e-300 0.3e-6), a row with depth 1e300. Expected: each refused naming constant/indenterProperties, the entry or the row and its item, the valid range; nothing written (no force.dat, no restart.h5).
. "$(dirname "$0")/../lib.sh"
ind; F=constant/indenterProperties
vals $F radius 0 1e300 -- cellIndentationFoam
vals $F tolerance 0 -- cellIndentationFoam
vals $F holdGrowth 1 0.9999999999999999 -- cellIndentationFoam
vals $F maxDeltaT 0 -- cellIndentationFoam
vals $F penaltyFactor 0 -- cellIndentationFoam
cp $F $W/i0; for r in "(A load 0.3e-6 [m] 0.3e-6)" "(B hold 0 0)" "(A load 0 0.3e-6)" "(A load 1e-300 0.3e-6)" "(A load 0.3e-6 1e300)"; do cp $W/i0 $F; /usr/bin/python3 - $F "$r" <<'P'
import sys, re
p, r = sys.argv[1:3]; t = open(p).read(); i = t.index('protocol'); j = t.index('(', i); k = t.index('\n', j)
open(p, 'w').write(t[:k + 1] + '    ' + r + '\n' + t[k + 1:])
P
  tryt 150 "row $r" cellIndentationFoam; echo "      results: $(ls postProcessing/indentation 2>/dev/null | tr '\n' ' ')"; rm -rf postProcessing; done; cp $W/i0 $F
