#!/bin/bash
# CASETIMEOUT=900
# o06 (fix19h's bad rank's message in a 2-rank restart, adv49b i23 / adv50a k02, varied: other fields and patches, both
# ranks bad, the 3D quarter): pbd (2 ranks, 2e-09 on both) restarted to 3e-9 with -acceptEdited after: (a) processor0's
# rho procBoundary0to1 value[0] = -1 (the master's processor patch: k02 (f)'s row on the other rank and field),
# (b) processor1's rho cell 3 = -1 AND processor0's rhoE cell 5 = nan (both ranks bad), (c) processor1's rhoU cell 3 =
# (1e300 0 0) (momentum beyond any state), (d) processor1's rho on a physical patch (its first non-processor patch with
# a value list) value[0] = -1; (e) the quarter q (2 ranks, 3D) restarted to 3e-9 with processor1's rho cell 0 = -1.
# Each: rc 1 within seconds, every bad rank's cell/face, field and file named, no hang (180 s), no signal or MPI trace.
. "$(dirname "$0")/../lib.sh"
pbd; rs; rm -f .runLock; cd $W; mv pblast b0
again() { cd $W; rm -rf pblast; cp -a b0 pblast; cd pblast; }
one() { local l=$1; shift; local s=$(date +%s); tryt 180 "$l" "$@"; echo "   $(( $(date +%s) - s )) s | sig: $(sig) | MPI lines: $(grep -a -c 'MPI_ERR\|ORTE_ERROR\|MPI_ABORT' $W/try.log) | FATAL blocks: $(grep -a -c 'FATAL' $W/try.log) | End: $(grep -a -c '^End' $W/try.log) | times: $(ls -d processor1/[0-9]* 2>/dev/null | tr '\n' ' ')"
  echo "   msg: $(msg 10)"; echo "   names: rank 0: $(grep -a -c 'rank 0' $W/try.log), rank 1: $(grep -a -c 'rank 1' $W/try.log), cell: $(grep -a -c 'cell [0-9]' $W/try.log), face/patch: $(grep -a -c -i 'face\|procBoundary\|patch' $W/try.log)"; }
P="mpirun -np 2 cellBlastFoam -parallel -acceptEdited"
again; setbb processor0/2e-09/rho procBoundary0to1 0 -1; one "(a) processor0 rho procBoundary0to1 value[0] -1" $P
again; fset processor1/2e-09/rho internal 3 -1; fset processor0/2e-09/rhoE internal 5 nan; one "(b) processor1 rho cell 3 -1 and processor0 rhoE cell 5 nan" $P
again; fset processor1/2e-09/rhoU internal 3 1e300 0 0; one "(c) processor1 rhoU cell 3 (1e300 0 0)" $P
again; pp=$(/usr/bin/python3 -c "
import re; t = open('processor1/2e-09/rho', 'rb').read().decode('latin1'); b = t[t.index('boundaryField'):]
for m in re.finditer(r'\n    (\w+)\s*\{([^}]*)\}', b):
    if not m.group(1).startswith('procBoundary') and 'value' in m.group(2) and 'nonuniform' in m.group(2): print(m.group(1)); break")
echo "   physical patch with a value list on processor1: ${pp:-none}"; [ -n "$pp" ] && { setbb processor1/2e-09/rho $pp 0 -1; one "(d) processor1 rho $pp value[0] -1" $P; }
cd $W; rm -rf pblast b0; q; qEnd 3e-9; latest; rm -f .runLock; fset processor1/2e-09/rho internal 0 -1; one "(e) quarter: processor1 rho cell 0 -1" mpirun -np 2 cellBlastFoam -parallel -acceptEdited
