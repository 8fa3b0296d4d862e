#!/bin/bash
# CASETIMEOUT=600
# p33 (new, class 2/3: p32's linked constant/ written through by the other case's tools): the finished preview A (bd) and
# B, a fresh copy of the tutorial whose constant/ is a symbolic link to A's constant/: (a) B's `./Allrun -noRun` with
# another -cell (its cellMesh and blockMesh write constant/cell.msh and constant/polyMesh: A's), then A's restart to 3e-9;
# (b) in B, `solidToFoam` of A's solid.h5 copy (writes constant/solid: A's). Expected: B's tools refuse to write into
# another case's constant/ holding results (or A's restart names the replaced mesh); A's mesh replaced under its results
# without a word = DATALOSS.
. "$(dirname "$0")/../lib.sh"
bd; A=$PWD; sums > $W/sA; msh > $W/m0
cd $W; cp -r $ROOT/tutorials/blast/axisymmetricPreview B; cd B; rm -rf constant; ln -s $A/constant constant
tryt 400 "(a) B's ./Allrun -noRun -cell 0.7e-6 (B/constant a link to A's)" ./Allrun -noRun -noPlots -noVTK -h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.7e-6 -Z 20e-6; echo "   said: $(grep -a -m2 -i 'error\|link\|refus' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-300)"
cd $A; echo "   A's meshes: $( [ "$(msh)" = "$(cat $W/m0)" ] && echo kept || echo "REPLACED ($(cat $W/m0) -> $(msh))") | A changed: $(changed $W/sA | cut -c1-300)"
latest; blastEnd 3e-9 1e-9; rm -f .runLock; tryt 300 "(a2) A's restart to 3e-9 after B's Allrun" cellBlastFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | said: $(msg 3 | cut -c1-300)"
