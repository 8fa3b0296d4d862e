#!/bin/bash
# CASETIMEOUT=900
# j08 (class 1, fix19e's rank record check (adv48b g12) varied): the finished 2-rank preview pbd, startFrom latestTime,
# endTime 3e-9, `mpirun -np 2 cellBlastFoam -parallel` with: (a) processor0/2e-09/uniform removed (the master's), (b) both
# ranks' uniform/inputDigests removed, (c) processor1's inputDigests a directory, (d) processor1's inputDigests a symbolic
# link to processor0's, (e) processor1/2e-09 removed whole (the ranks' latest times differ), (f) processor1/2e-09/
# .writeCommitted removed (rank 1's latest time incomplete), (g) processor0/2e-09/uniform/time removed; (h) the 3D quarter
# (q, 2 ranks): processor1/2e-09/uniform/inputDigests removed. Each refused at once on every rank (rc != 0 within 120 s,
# no hang) naming the rank's directory and what is missing, nothing written; or (e), (f) if continued, from one time on
# both ranks (never ranks at two times).
. "$(dirname "$0")/../lib.sh"
pbd; rs; rm -f .runLock; cp -a . ../keep
one() { local l=$1; shift; sums > ../s0; tryt 120 "$l" mpirun -np 2 cellBlastFoam -parallel "$@"; echo "   sig: $(sig) | msg: $(msg 5 | cut -c1-600)"; cont; echo "   p0: $(ls -d processor0/[0-9]* processor0/*incomplete* 2>/dev/null | tr '\n' ' ')| p1: $(ls -d processor1/[0-9]* processor1/*incomplete* 2>/dev/null | tr '\n' ' ')| changed: $(changed ../s0 | cut -c1-300)"; cd $W; rm -rf pblast; cp -a keep pblast; cd pblast; }
rm -rf processor0/2e-09/uniform; one "(a) processor0/2e-09/uniform removed"
rm -f processor*/2e-09/uniform/inputDigests; one "(b) both ranks' inputDigests removed"
rm -f processor1/2e-09/uniform/inputDigests; mkdir processor1/2e-09/uniform/inputDigests; one "(c) processor1 inputDigests a directory"
rm -f processor1/2e-09/uniform/inputDigests; ln -s ../../../processor0/2e-09/uniform/inputDigests processor1/2e-09/uniform/inputDigests; one "(d) processor1 inputDigests a link to processor0's"
rm -rf processor1/2e-09; one "(e) processor1/2e-09 removed"
rm -f processor1/2e-09/.writeCommitted; one "(f) processor1/2e-09/.writeCommitted removed"
rm -f processor0/2e-09/uniform/time; one "(g) processor0/2e-09/uniform/time removed"
cd $W; q; latest; qEnd 3e-9; rm -f .runLock; rm -f processor1/2e-09/uniform/inputDigests; sums > ../s0
tryt 240 "(h) 3D quarter: processor1/2e-09/uniform/inputDigests removed" mpirun -np 2 cellBlastFoam -parallel; echo "   sig: $(sig) | msg: $(msg 5 | cut -c1-600) | changed: $(changed ../s0 | cut -c1-300)"
