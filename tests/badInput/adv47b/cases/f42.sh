#!/bin/bash
# f42 (class 4, maxCo at its bound and one ulp each side): sod's maxCo 1 (the bound of (0, 1]) and 0.9999999999999999: accepted, runs end rc 0; 1.0000000000000002: refused naming maxCo and (0, 1].
. "$(dirname "$0")/../lib.sh"
sod; cp system/controlDict ../cd0
for v in 1 0.9999999999999999 1.0000000000000002; do cp ../cd0 system/controlDict; sete system/controlDict maxCo $v; tryt 120 "maxCo $v" rhoRiemannFoam; rm -rf [1-9]* 0.[0-9]* postProcessing; done
