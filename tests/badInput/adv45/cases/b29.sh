#!/bin/bash
# b29 (class 4, planeWave odd option values): on a blast case with a planeWaveInflow top (iblast): -inflow, -Z, -dz, -endTime, -radius, -maxSteps, -maxCells each set to 1e308, 1e-400, -0, a hex number, 4.9e-324, 1e400 (with -inflow 20e-6 -Z 40e-6 for the others): each refused naming the option, the value and the range (or, if valid, the wave computed); no traceback; constant/inflowWave unchanged?
. "$(dirname "$0")/../lib.sh"
iblast; md5sum constant/inflowWave > ../m
for o in -inflow -Z -dz -endTime -maxSteps -maxCells; do for v in 1e308 1e-400 -0 0x1p-20 4.9e-324 1e400; do
  case $o in -inflow) a="-inflow $v -Z 40e-6";; -Z) a="-inflow 20e-6 -Z $v";; *) a="$IW $o $v";; esac
  timeout -s KILL 60 planeWave $a > ../log.p 2>&1; echo "$o $v: rc=$? | $(grep -a -m1 -i 'error\|refus\|Traceback\|written\|same' ../log.p | cut -c1-200)"; done; done; echo "   inflowWave: $(md5sum -c ../m 2>&1 | awk '{print $2}')"
