#!/bin/bash
# CASETIMEOUT=900
# h09 (class 4, numberText's edges in the Python tools: -DBL_MAX, DBL_MAX, 1e308, -1e308, 1e309, inf, -inf, nan, -0,
# 4.9e-324, 1e-310): planeWave -maxSteps (the finished preview), sweepCase -maxRuns and -values (sod's maxCo), pulseStudy
# sampleInterval (with maxPoints 1 appended: nothing may run), calibrateCell relativeError. Each refused (rc != 0, no
# Traceback) naming the option/entry, the file and the valid range, or accepted if in range (cut at 30 s). One line each.
. "$(dirname "$0")/../lib.sh"
V="-1.7976931348623157e308 1.7976931348623157e308 1e308 -1e308 1e309 inf -inf nan -0 4.9e-324 1e-310"
show() { local rc=$1; echo "   [$2] rc=$rc traceback=$(grep -a -c Traceback $W/try.log) | $(grep -a -m1 -A2 'FATAL\|[Ee]rror\|refused\|outside\|not a\|invalid\|must' $W/try.log | grep -av '^ *$\|^-->\|From function' | head -2 | tr '\n' ' ' | tr -s ' ' | cut -c1-330)"; }
bd; echo "== planeWave -maxSteps"; for v in $V; do timeout -s KILL 30 planeWave -maxSteps $v > $W/try.log 2>&1; show $? $v; killIn $W; done
cd $W; sod; echo "== sweepCase -maxRuns (2 values)"; for v in $V; do timeout -s KILL 30 sweepCase -entry system/controlDict/maxCo -values "0.4 0.5" -maxRuns $v -run rhoRiemannFoam -output "t=0.007/uniform/time:/value +([0-9.e+-]+);/" -name "m$RANDOM" > $W/try.log 2>&1; show $? $v; killIn $W; done
echo "== sweepCase -values"; for v in $V; do timeout -s KILL 30 sweepCase -entry system/controlDict/maxCo -values "$v" -run rhoRiemannFoam -output "t=0.007/uniform/time:/value +([0-9.e+-]+);/" -name "v$RANDOM" > $W/try.log 2>&1; show $? $v; killIn $W; done
echo "   folders left in $W: $(ls $W | tr '\n' ' ')"
cd $W; study; echo "maxPoints 1;" >> system/pulseStudyDict; cp system/pulseStudyDict ../pd; echo "== pulseStudy sampleInterval"
for v in $V; do cp ../pd system/pulseStudyDict; sete system/pulseStudyDict sampleInterval $v; timeout -s KILL 30 pulseStudy > $W/try.log 2>&1; show $? $v; killIn $W; rm -rf postProcessing; done
cd $W; cal; cp system/calibrationDict ../cd; echo "== calibrateCell relativeError"
for v in $V; do cp ../cd system/calibrationDict; sete system/calibrationDict relativeError $v; timeout -s KILL 30 calibrateCell > $W/try.log 2>&1; show $? $v; killIn $W; rm -rf postProcessing constant/solidProperties.calibrated; done
