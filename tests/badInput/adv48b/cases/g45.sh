#!/bin/bash
# g45 (class 4, a depth the cell does not have) the smoke indentation with one load row to 20 um ((A load 0.3e-6 20e-6); the cell is 7.9 um high, the bead would pass the substrate): refused before the run naming the row and the cell's height, or stopped with a message naming the depth reached and why; never exit 0 with forces past the substrate.
. "$(dirname "$0")/../lib.sh"
ind; P="(A load 0.3e-6 20e-6)"; /usr/bin/python3 - constant/indenterProperties "$P" <<'P'
import re, sys
p, rows = sys.argv[1:3]; t = open(p).read()
t = re.sub(r"(?ms)^protocol\s*\(.*?^\);", "protocol\n(\n" + rows + "\n);", t, count=1); open(p, "w").write(t)
P
tryt 400 "$P" cellIndentationFoam; tail -3 $W/try.log | cut -c1-200; after; tail -2 postProcessing/indentation/force.dat 2>/dev/null | cut -c1-150
