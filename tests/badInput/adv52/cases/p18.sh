#!/bin/bash
# CASETIMEOUT=900
# p18 (new, class 5/4: the benchmark analysis scripts that take a case, on what they cannot read; fix19h's guard reached
# checkLongRun.py and incidentWindow.py only): each of bench/blast/{interfaceProbeVariants,interfaceProfile,layeredVerify,
# nucleusIndicators,probeOvershoot,residualFlow,residualFlow3D,restVonMises,solidStrainNoise,temperatureRise,planeWaveTable}
# .py and analysis/probePoints.py on (a) an empty folder and (b) the finished preview bd (no planeWave reference, 2 ns
# only); restBand.py, footLadder.py, patchLadder.py on the same as their "cases"; compareRuns.py bd bd-with-solid.h5-cut.
# Each: one line naming what is missing (rc != 0) or a result; a Python traceback = CRASH (low).
. "$(dirname "$0")/../lib.sh"
B=$ROOT/bench/blast; mkdir -p $W/empty; bd; C=$PWD
run1() { local l=$1; shift; tryt 60 "$l" /usr/bin/python3 "$@"; echo "   traceback: $(grep -a -c Traceback $W/try.log) | last: $(grep -a -v '^ *$' $W/try.log | tail -1 | cut -c1-200)"; }
for s in interfaceProbeVariants interfaceProfile layeredVerify nucleusIndicators probeOvershoot residualFlow residualFlow3D restVonMises solidStrainNoise temperatureRise analysis/probePoints restBand analysis/footLadder analysis/patchLadder; do
  run1 "(a) $s.py on an empty folder" $B/$s.py $W/empty; run1 "(b) $s.py on bd" $B/$s.py $C; done
run1 "(a) planeWaveTable.py on an empty folder" $B/planeWaveTable.py $W/empty $W/pt.md; run1 "(b) planeWaveTable.py on bd" $B/planeWaveTable.py $C $W/pt2.md
cp -a $C $W/cut; s=$(stat -c %s $W/cut/solid/solid.h5); truncate -s $((s/2)) $W/cut/solid/solid.h5
run1 "(c) compareRuns.py bd and bd with solid.h5 cut to half" $B/compareRuns.py $C $W/cut
