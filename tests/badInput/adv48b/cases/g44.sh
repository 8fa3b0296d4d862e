#!/bin/bash
# g44 (class 4/6, steps no run can finish) the smoke indentation: (a) maxDepthIncrement 1e-299 (3e27 steps for 0.3 um), (b) holdDeltaT0 1e-299 with holdGrowth 1, (c) a load row at rate 0 ((A load 0 0.3e-6): never reaches its depth), (d) a hold of 1e300 s: each refused before the run naming the entry or row and the number of steps or the time it means; never a run that cannot end (60 s here: HANG).
. "$(dirname "$0")/../lib.sh"
ind; each constant/indenterProperties "maxDepthIncrement 1e-299" -- cellIndentationFoam
cp constant/indenterProperties ../ip0; sete constant/indenterProperties holdDeltaT0 1e-299; sete constant/indenterProperties holdGrowth 1; try "(b) holdDeltaT0 1e-299, holdGrowth 1" cellIndentationFoam; rm -rf postProcessing [1-9]*; cp ../ip0 constant/indenterProperties
P="(A load 0 0.3e-6)"; /usr/bin/python3 - constant/indenterProperties "$P" <<'P'
import re, sys
p, rows = sys.argv[1:3]; t = open(p).read()
t = re.sub(r"(?ms)^protocol\s*\(.*?^\);", "protocol\n(\n" + rows + "\n);", t, count=1); open(p, "w").write(t)
P
try "(c) $P" cellIndentationFoam; rm -rf postProcessing [1-9]*; cp ../ip0 constant/indenterProperties
P="(A load 0.3e-6 0.3e-6) (B hold 0 1e300)"; /usr/bin/python3 - constant/indenterProperties "$P" <<'P'
import re, sys
p, rows = sys.argv[1:3]; t = open(p).read()
t = re.sub(r"(?ms)^protocol\s*\(.*?^\);", "protocol\n(\n" + rows + "\n);", t, count=1); open(p, "w").write(t)
P
try "(d) $P" cellIndentationFoam; rm -rf postProcessing [1-9]*
