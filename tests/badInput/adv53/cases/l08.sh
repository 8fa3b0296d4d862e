#!/bin/bash
# CASETIMEOUT=600
# l08 (new, class 6: a small stack limit, `ulimit -s`, as a batch system or a shared account sets): (a) cellMesh in the
# quarter mesh folder (qm, gmsh inside), (b) the short preview sb (cellBlastFoam), (c) solidToFoam on bd, (d) planeWave
# on bd, (e) cellIndentationFoam on ind, each under ulimit -s 256 (KB), then 64. Expected: each runs or stops naming the
# limit; a SIGSEGV without a word = CRASH (low); a result written half = DATALOSS.
. "$(dirname "$0")/../lib.sh"
lim() { local s=$1 l=$2; shift 2; tryt 300 "$l (ulimit -s $s)" bash -c "ulimit -s $s; exec \"\$@\"" _ "$@"; echo "   rc-sig lines $(sig) | Segm: $(grep -a -c -i 'segmentation\|SIGSEGV\|stack' $W/try.log) | last: $(grep -a -v '^ *$' $W/try.log | tail -1 | cut -c1-200)"; }
for s in 256 64; do
  cd $W; rm -rf m; qm; lim $s "(a) cellMesh (quarter)" cellMesh
  cd $W; rm -rf blast; sb; lim $s "(b) cellBlastFoam (short preview)" cellBlastFoam
  cd $W; rm -rf blast; bd; rm -rf constant/solid; lim $s "(c) solidToFoam" solidToFoam solid/solid.h5
  lim $s "(d) planeWave" planeWave -case .
  cd $W; rm -rf ind; ind; lim $s "(e) cellIndentationFoam" cellIndentationFoam; done
