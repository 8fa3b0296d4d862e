#!/bin/bash
# CASETIMEOUT=900
# p09 (new, class 6: a memory limit, `ulimit -v`, on the tools that were never run under one; cellMesh was, m01): (a) the
# smoke indentation (ind) under ulimit -v 150000 / 400000 KB; (b) planeWave -case on bd under ulimit -v 300000 (its 1D
# column); (c) the preview restart (bd, to 3e-9) under ulimit -v 400000; (d) solidToFoam under ulimit -v 100000. Each: an
# error naming memory (bad_alloc caught, "not enough memory") rc != 0 and the case's files as they were, or the run
# ends; a signal or an abort with no message = CRASH; results half written and taken as good later = DATALOSS.
. "$(dirname "$0")/../lib.sh"
lim() { local l=$1 n=$2; shift 2; tryt 300 "$l under ulimit -v $n" bash -c "ulimit -v $n; exec $*"; echo "   sig lines: $(sig) | said: $(grep -a -m2 -i 'memory\|alloc\|fatal\|error' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-250) | End: $(grep -a -c '^End' $W/try.log)"; }
ind; same0; lim "(a1) cellIndentationFoam" 150000 cellIndentationFoam; same1; rm -rf postProcessing [1-9]* .runLock; same0
lim "(a2) cellIndentationFoam" 400000 cellIndentationFoam; after
cd $W; bd; C=$PWD; same0; lim "(b) planeWave -case" 300000 planeWave -case $C; echo "   planeWave outputs: $(ls postProcessing/planeWave/0 2>/dev/null | tr '\n' ' ')"
rs; rm -f .runLock; lim "(c) cellBlastFoam restart to 3e-9" 400000 cellBlastFoam; echo "   times: $(ls -d [0-9]* .[0-9]* 2>/dev/null | tr '\n' ' ') | lock: $(lockOf | cut -c1-60)"
rm -rf constant/solid; lim "(d) solidToFoam" 100000 solidToFoam solid/solid.h5; echo "   constant/solid: $(ls constant/solid 2>/dev/null | tr '\n' ' ' | cut -c1-100)"
