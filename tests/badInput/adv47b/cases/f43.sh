#!/bin/bash
# f43 (class 4, deltaT at the reader's edge): sod's deltaT 1e-300 (the bound of the number scan: non-zero <= 1e-300 refused), 1.0000000000000001e-300 (readable, but ~1e296 steps), 4.9e-324 (subnormal), -0 and 0: each refused before a step, naming deltaT (and the range or maxSteps); never a run.
. "$(dirname "$0")/../lib.sh"
sod; cp system/controlDict ../cd0
for v in 1e-300 1.0000000000000001e-300 4.9e-324 -0 0; do cp ../cd0 system/controlDict; sete system/controlDict deltaT $v; tryt 60 "deltaT $v" rhoRiemannFoam; ls -d [1-9]* 0.[0-9]* 2>/dev/null | head -2; rm -rf [1-9]* 0.[0-9]* postProcessing; done
