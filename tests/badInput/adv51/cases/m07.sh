#!/bin/bash
# CASETIMEOUT=900
# m07 (fix19g's processor directories before the Time, adv49b i32 (b), varied; and the two HANGs adv50a found on
# fix19g's first commit): the finished 2-rank preview pbd restarted to 3e-9 (`mpirun -np 2 cellBlastFoam -parallel`):
# (a) processor0 missing (the master's own), (b) processor1 a regular file, (c) processor1 a dangling symbolic link,
# (d) processor1 a symbolic link to processor0 (two ranks, one directory), (e) processor1 unreadable (chmod 000),
# (f) a stray processor2 beside both (-np 2), (g) processor1 renamed processor01, (h) -np 3 on 2 directories,
# (i) -np 2 in the undecomposed case (processor* removed), (j) -np 1 -parallel, (k) the collated format:
# `decomposePar -fileHandler collated` (processors2/) and `mpirun -np 2 cellBlastFoam -parallel -fileHandler collated`,
# (l) the control: unchanged restart. Each within 120 s: refused rc 1 naming the directories (or run right), every
# rank ended (no rank left running), nothing of the case changed.
. "$(dirname "$0")/../lib.sh"
pbd; rs; rm -f .runLock; cp -a . ../p0; C=$PWD
back() { cd $W; chmod -R u+rwx pblast 2>/dev/null; rm -rf pblast; cp -a p0 pblast; cd pblast; }
one() { local l=$1; shift; sums > $W/s0; local t0=$(date +%s); tryt 120 "$l" "$@"; local rc=$?
  echo "   $(( $(date +%s) - t0 )) s | sig: $(sig) | left running: $(inDir $C | cut -c1-200) | MPI lines: $(grep -a -c 'MPI_ABORT\|MPI_ERR\|mpirun has exited\|mpirun noticed' $W/try.log) | changed: $(changed $W/s0 | cut -c1-200)"
  echo "   msg: $(msg 6 | cut -c1-600)"; killIn $C; }
np2() { one "$1" mpirun -np ${2:-2} cellBlastFoam -parallel ${3:-}; }
back; rm -rf processor0; np2 "(a) processor0 missing"
back; rm -rf processor1; echo "not a directory" > processor1; np2 "(b) processor1 a regular file"
back; rm -rf processor1; ln -s nosuch processor1; np2 "(c) processor1 a dangling link"
back; rm -rf processor1; ln -s processor0 processor1; np2 "(d) processor1 a link to processor0"; echo "   processor0 times now: $(ls -d processor0/[0-9]* | tr '\n' ' ')"
back; chmod 000 processor1; np2 "(e) processor1 chmod 000"; chmod 755 processor1
back; cp -a processor1 processor2; np2 "(f) a stray processor2 beside processor0/1, -np 2"; echo "   times: $(ls -d processor*/[0-9]* | tr '\n' ' ')"
back; mv processor1 processor01; np2 "(g) processor1 renamed processor01"
back; np2 "(h) -np 3 on 2 processor directories" 3
back; rm -rf processor*; np2 "(i) -np 2 in the undecomposed case"
back; one "(j) mpirun -np 1 cellBlastFoam -parallel" mpirun -np 1 cellBlastFoam -parallel
cd $W; rm -rf pblast p0; pblast; rm -rf processor*; timeout -s KILL 120 decomposePar -fileHandler collated > log.dc 2>&1; echo "(k) decomposePar -fileHandler collated: rc $? | $(ls -d processor* | tr '\n' ' ')"; C=$PWD
np2 "(k) mpirun -np 2 cellBlastFoam -parallel -fileHandler collated" 2 "-fileHandler collated"; echo "   times: $(ls -d [0-9]* processor*/[0-9]* 2>/dev/null | tr '\n' ' ')"
np2 "(k2) the same without -fileHandler" 2
cd $W; rm -rf pblast; pbd; rs; rm -f .runLock; C=$PWD; np2 "(l) the unchanged restart (control)"; echo "   times: $(ls -d processor0/[0-9]* | tr '\n' ' ')"
