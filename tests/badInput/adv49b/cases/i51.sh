#!/bin/bash
# i51 (class 4, values valid alone but not together, the structured cell with the shortened column and a wide band): the
# preview `Allrun -h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 40e-6 -inflow 14e-6 -meshType structured -motionDistance
# 12e-6 -endTime 2e-9` (the band of moving points reaches the planeWaveInflow top at 14 um: the cell's top is at 7.9 um):
# refused naming -motionDistance and -inflow, or run with the top patch's points fixed (exit 0, finite logs, the top's
# inflow probe unchanged against motionDistance 5e-6 (b)); never a moving inflow boundary without a word, no crash.
. "$(dirname "$0")/../lib.sh"
O="-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 40e-6 -inflow 14e-6 -meshType structured -endTime 2e-9 -writeInterval 1e-9 -noPlots -noVTK"
prev; tryt 600 "(a) -motionDistance 12e-6" ./Allrun $O -motionDistance 12e-6; tail -3 $W/try.log | cut -c1-200 | sed 's/^/   /'; after; A=$PWD; cd $W; mv c a
prev; tryt 600 "(b) -motionDistance 5e-6" ./Allrun $O -motionDistance 5e-6; after; cd $W/a; closeTo $W/c
