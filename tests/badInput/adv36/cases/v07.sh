#!/bin/bash
# v07: sod: -overwrite with a late-refused input (a function object listing an unknown field) over a finished run
. "$(dirname "$0")/../lib.sh"
sodDone; sums > ../before
cat >> system/controlDict <<'X'
functions { pr { type probes; libs ("libsampling.so"); fields (pp); probeLocations ((0 0 0)); } }
X
rhoRiemannFoam -overwrite > log.ow 2>&1; echo "rc=$?"; grep -a -A3 FATAL log.ow | head -5
sums > ../after; diff <(grep -v controlDict ../before) <(grep -v controlDict ../after) && echo "results unchanged"
