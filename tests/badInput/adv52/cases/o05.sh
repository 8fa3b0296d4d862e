#!/bin/bash
# CASETIMEOUT=900
# o05 (fix19h's restart from times written with fewer than 17 digits, refused, adv51 m05 (e) / adv50b k58, varied: the
# other solver, 2 ranks, the commit marker's record edited): (a) waterPulseWall (rhoRiemannFoam, ascii) written with
# writePrecision 8 to 2e-8, restarted to 4e-8: refused naming 8; (b) the same with -acceptEdited: runs, said;
# (c) the 2-rank preview (pblast) written with writePrecision 6 (writeFormat ascii) to 1e-9, restarted to 2e-9 on 2 ranks:
# refused on every rank, no hang; (d) the preview written with writePrecision 5, the marker's "written 5 ascii" line edited
# to "written 17 ascii" (a user who "fixes" the record), writePrecision 17 again: refused (marker damaged) or SILENT (runs
# as exact: p compared with the uninterrupted run); (e) the marker's written line removed (judged by the controlDict
# with a warning, as a time of an earlier build?). Never a silent inexact restart.
. "$(dirname "$0")/../lib.sh"
ctl() { sed -i "s/^writeFormat .*/writeFormat $1;/; s/^writePrecision .*/writePrecision $2;/" system/controlDict; }
res() { echo "   End: $(grep -a -c '^End' $W/try.log) | digits lines: $(grep -a -c -i 'writePrecision\|digits' $W/try.log) | $(grep -a -m1 -i -B1 -A1 'writePrecision\|digits' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-400)"; }
cd $W; cp -r $ROOT/tutorials/verification/waterPulseWall wp; cd wp; cp -r 0.orig 0; blockMesh > log.blockMesh 2>&1; cp -a . ../wp0
ctl ascii 8; sed -i 's/^endTime .*/endTime 2e-8;/' system/controlDict; tryt 300 "(a0) waterPulseWall to 2e-8 with writePrecision 8" rhoRiemannFoam
echo "   marker: $(grep -a '^written' 2e-08/.writeCommitted)"; ctl ascii 17; sed -i 's/^endTime .*/endTime 4e-8;/' system/controlDict; latest; cp -a . ../wpA
tryt 300 "(a) restart to 4e-8" rhoRiemannFoam; res
tryt 300 "(b) restart to 4e-8 -acceptEdited" rhoRiemannFoam -acceptEdited; res; echo "   times: $(ls -d [0-9]* | tr '\n' ' ')"
cd $W; pblast; blastEnd 1e-9 1e-9; ctl ascii 6; rm -rf processor*; decomposePar > log.decompose 2>&1; tryt 300 "(c0) 2 ranks to 1e-9 with writePrecision 6" mpirun -np 2 cellBlastFoam -parallel
echo "   markers: $(grep -a -h '^written' processor*/1e-09/.writeCommitted | tr '\n' ' ')"; ctl ascii 17; latest; blastEnd 2e-9 1e-9
tryt 300 "(c) 2-rank restart to 2e-9" mpirun -np 2 cellBlastFoam -parallel; res; echo "   ranks said: $(grep -a -c 'FOAM FATAL' $W/try.log) fatal blocks | processor0 times: $(ls -d processor0/[0-9]* | tr '\n' ' ')"
cd $W; rm -rf blast; blast; mv $W/blast $W/dd; cd $W/dd; blastEnd 1e-9 1e-9; ctl ascii 5; tryt 300 "(d0) preview to 1e-9 with writePrecision 5" cellBlastFoam; ctl ascii 17; latest; blastEnd 2e-9 1e-9
echo "   marker: $(grep -a '^written' 1e-09/.writeCommitted)"; cp -a . $W/d0
sed -i 's/^written 5 ascii/written 17 ascii/' 1e-09/.writeCommitted; echo "   edited marker: $(grep -a '^written' 1e-09/.writeCommitted)"
tryt 300 "(d) restart with the marker's written line edited to 17" cellBlastFoam; res
[ -f 2e-09/p ] && { D=$PWD; cd $W; bd; /usr/bin/python3 -c "
import sys, numpy as np; from neuronFsi import foamField as f
a = np.asarray(f.internalField(sys.argv[1])); b = np.asarray(f.internalField(sys.argv[2]))
print('   (d) ran: 2e-09/p largest difference from the uninterrupted run %.3g Pa of %.3g Pa' % (np.abs(a-b).max(), np.abs(b).max()))" $D/2e-09/p $W/blast/2e-09/p; }
cd $W; rm -rf d1; cp -a d0 d1; cd d1; sed -i '/^written /d' 1e-09/.writeCommitted; tryt 300 "(e) restart with the marker's written line removed" cellBlastFoam; res
