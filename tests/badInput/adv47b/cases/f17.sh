#!/bin/bash
# f17 (class 1/3, one rank of the 3D quarter SIGKILLed): q restarted on 2 ranks to 6e-9; once processor1/3e-09 is committed, rank 1's cellBlastFoam is SIGKILLed: the other rank and mpirun must end within 60 s (no hang). Then restart on 2 ranks to 6e-9: continues from the last time both ranks committed, rc 0, and its logs equal those of an unbroken restart 2e-9 -> 6e-9 (B), exact.
. "$(dirname "$0")/../lib.sh"
q; mv $W/q $W/B; cd $W/B; latest; qEnd 6e-9; tryt 280 "B: unbroken restart to 6e-9" mpirun -np 2 cellBlastFoam -parallel
q; latest; qEnd 6e-9; mpirun -np 2 cellBlastFoam -parallel > log.bg 2>&1 & p=$!; waitFor 200 test -f processor1/3e-09/.writeCommitted
r1=""; for d in /proc/[0-9]*; do c=$(tr '\0' ' ' < $d/cmdline 2>/dev/null); case "$c" in cellBlastFoam*) grep -qa 'OMPI_COMM_WORLD_RANK=1' $d/environ 2>/dev/null && r1=${d#/proc/};; esac; done
echo "   rank 1 pid $r1 killed at $(ls -d processor1/[0-9]* | tr '\n' ' ')"; kill -KILL $r1; i=0; while kill -0 $p 2>/dev/null && [ $i -lt 600 ]; do sleep 0.1; i=$((i+1)); done
kill -0 $p 2>/dev/null && { echo "   HANG: mpirun still running 60 s after the kill"; killIn $W/q; }; wait $p; echo "   mpirun rc=$? after $((i/10)) s"
echo "   rank0: $(ls -d processor0/[0-9]* processor0/.*incomplete* 2>/dev/null | tr '\n' ' ') rank1: $(ls -d processor1/[0-9]* 2>/dev/null | tr '\n' ' ')"
tryt 280 "restart on 2 ranks" mpirun -np 2 cellBlastFoam -parallel; cont; sameSeries $W/B; echo "   solid.h5 $(h5same solid/solid.h5 $W/B/solid/solid.h5)"
