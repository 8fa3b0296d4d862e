#!/bin/bash
# f70 (class 6, rhoRiemannFoam's maxSteps at the step estimate): sod with adjustTimeStep no, deltaT 1e-6 (0.007 / 1e-6 = 7000.000000000001 in double): maxSteps 1 (refused, naming the estimate), 7000 (the steps the run takes: accepted, or refused saying the count as more than 7000), 7001 (accepted), 6999 (refused naming the estimate and maxSteps).
. "$(dirname "$0")/../lib.sh"
sod; sete system/controlDict adjustTimeStep no; sete system/controlDict deltaT 1e-6; cp system/controlDict ../cd0
for m in 1 7000 7001 6999; do cp ../cd0 system/controlDict; echo "maxSteps $m;" >> system/controlDict; tryt 120 "maxSteps $m" rhoRiemannFoam; echo "   times: $(ls -d [0-9]* | tr '\n' ' ')"; rm -rf [1-9]* 0.[0-9]* postProcessing; done
