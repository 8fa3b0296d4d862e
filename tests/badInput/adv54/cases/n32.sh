#!/bin/bash
# CASETIMEOUT=600
# n32 (new, class 6: a memory limit, `ulimit -v`, on the Python tools p09 did not run under one - p09 ran planeWave):
# under ulimit -v 60000, 120000 and 200000 (KiB): plotIndentation.py on idn, plotBlast.py and incidentWindow.py on p8,
# fluidWedgeMesh.py (the preview's sizes) in a scratch folder, sweepCase -help. Expected: each runs or fails in one line
# naming memory (MemoryError / "not enough memory"), rc != 0, nothing half-written; a traceback = CRASH low; a signal =
# CRASH.
. "$(dirname "$0")/../lib.sh"
vlim() { local n=$1 l=$2; shift 2; tryt 200 "$l (ulimit -v $n)" bash -c "ulimit -v $n; exec \"\$@\"" _ "$@"; echo "   sig $(sig) | traceback $(grep -a -c Traceback $W/try.log) | last: $(grep -a -v '^ *$' $W/try.log | tail -n 1 | cut -c1-200)"; }
idn; I=$PWD; cd $W; p8; P=$PWD; cp log.cellBlastFoam log.keep
for n in 60000 120000 200000; do cd $I; vlim $n "plotIndentation.py" /usr/bin/python3 $ROOT/tutorials/indentation/plotIndentation.py .
  cd $P; vlim $n "plotBlast.py" /usr/bin/python3 $ROOT/tutorials/blast/plotBlast.py .; vlim $n "incidentWindow.py" /usr/bin/python3 $ROOT/bench/blast/analysis/incidentWindow.py .
  mkdir -p $W/fw$n/system; cd $W/fw$n; vlim $n "fluidWedgeMesh.py" /usr/bin/python3 $ROOT/tutorials/blast/fluidWedgeMesh.py -h 0.25e-6 -far 2e-6 -Z 20e-6 -o system/blockMeshDict; echo "   blockMeshDict: $(stat -c %s system/blockMeshDict 2>/dev/null || echo none) B"
  vlim $n "sweepCase -help" sweepCase -help; done
