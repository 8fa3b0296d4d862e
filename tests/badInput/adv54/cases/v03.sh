#!/bin/bash
# CASETIMEOUT=900
# v03 (fix19j row "output folders that are links leaving the case", varied: the tools that are not solvers): A = p8 (the
# preview to 8 ns with planeWave's files), B = q8 (its pulse doubled): in B, (a) postProcessing/planeWave a symbolic link
# to A's postProcessing/planeWave: `planeWave -case .` in B; (b) B's own postProcessing/ moved to $W/Bpp and linked back
# from B (a link leaving the case that holds B's own files, as a user keeping results on another disk): planeWave,
# plotBlast.py; (c) the sod tube with postProcessing a
# link to another case's postProcessing: riemannError. Expected: (a) refused (A's reference.dat would be replaced by B's
# 100 MPa reference) or A kept: A's reference.dat replaced = DATALOSS; (b) B's own results through a link: a documented
# decision either way.
. "$(dirname "$0")/../lib.sh"
p8; A=$PWD; md5sum postProcessing/planeWave/0/* > $W/mA; cd $W; q8; rm -rf postProcessing/planeWave; ln -s $A/postProcessing/planeWave postProcessing/planeWave
tryt 300 "(a) planeWave in B, postProcessing/planeWave a link to A's" planeWave -case .; echo "   said: $(say 2 | cut -c1-300)"; echo "   A's planeWave files: $(cd $A; md5sum -c $W/mA 2>&1 | grep -c ': OK') of $(wc -l < $W/mA) kept; A's reference header: $(sed -n 1p $A/postProcessing/planeWave/0/reference.dat | cut -c1-120)"
cd $W; rm -rf q8; q8; B=$PWD; mv postProcessing $W/Bpp; ln -s $W/Bpp postProcessing; tryt 300 "(b) planeWave in B, postProcessing a link to B's own files elsewhere" planeWave -case .; echo "   said: $(say 2 | cut -c1-300)"
cp log.cellBlastFoam log.cellBlastFoam.x 2>/dev/null; tryt 300 "(b) plotBlast.py" /usr/bin/python3 $ROOT/tutorials/blast/plotBlast.py .; echo "   said: $(say 2 | cut -c1-300) | blastSummary in $W/Bpp: $(ls $W/Bpp/blastSummary.dat 2>/dev/null || echo none)"
cd $W; sodDone; S1=$PWD; mkdir -p $W/other/postProcessing/riemannError; mark $W/other/postProcessing/riemannError/notes.txt; rm -rf postProcessing; ln -s $W/other/postProcessing postProcessing
tryt 300 "(c) riemannError, postProcessing a link to another case's" riemannError; echo "   said: $(say 2 | cut -c1-300) | other: $(find $W/other -type f | tr '\n' ' ' | cut -c1-250)"; kept_ $W/other/postProcessing/riemannError/notes.txt
