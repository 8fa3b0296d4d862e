#!/bin/bash
# g36 (class 4, water probes where there is no water) the prepared preview, endTime 2e-11, fluidProbes probeLocations with (a) a point inside the cell (1e-7 5e-6 0), (b) a point outside the domain (1 1 0), (c) a point on the substrate wall (1e-7 0 0): (a) and (b) refused before the run naming the probe and why, or each probe's file says it has no value; never a column of made-up pressures.
. "$(dirname "$0")/../lib.sh"
blast; short; cp system/controlDict ../cd0
for pt in "(1e-7 5e-6 0)" "(1 1 0)" "(1e-7 0 0)"; do cp ../cd0 system/controlDict; /usr/bin/python3 - system/controlDict "$pt" <<'P'
import sys, re
p, pt = sys.argv[1:3]; t = open(p).read()
t = re.sub(r'(probeLocations\s*\(\s*)', lambda m: m.group(1) + pt + '\n            ', t, count=1); open(p, 'w').write(t)
P
  tryt 200 "probe $pt" cellBlastFoam; grep -a -i -m2 'probe.*not\|not found\|outside\|warn' $W/try.log | cut -c1-200; f=$(ls postProcessing/fluidProbes/0/p 2>/dev/null); [ -n "$f" ] && { grep -a '^#' $f | head -3 | cut -c1-150; tail -1 $f | cut -c1-150; }; rm -rf [1-9]* solid postProcessing; done
