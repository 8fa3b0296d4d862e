#!/bin/bash
# f45 (class 4, endTime at the start time written oddly): sod's endTime -0, 4.9e-324 and 1e-300: each refused before a step (a start that computes nothing, or below the reader) naming endTime; never exit 0 with nothing done.
. "$(dirname "$0")/../lib.sh"
sod; cp system/controlDict ../cd0
for v in -0 4.9e-324 1e-300; do cp ../cd0 system/controlDict; sed -i "s/^endTime .*/endTime $v;/" system/controlDict; grep -c "^endTime $v;" system/controlDict; tryt 60 "endTime $v" rhoRiemannFoam; ls -d [1-9]* 0.[0-9]* 2>/dev/null | head -2; rm -rf [1-9]* 0.[0-9]* postProcessing; done
