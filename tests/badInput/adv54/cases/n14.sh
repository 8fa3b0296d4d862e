#!/bin/bash
# CASETIMEOUT=600
# n14 (new, class 2: a case copied with hard links (`cp -al`, a cheap snapshot), then the Python tools re-run in the COPY:
# fix19i's ownCopy covers the solvers' appends, not the scripts' writes): (a) p8 copied with cp -al to C; in C,
# `planeWave -case C -Z 40e-6` (another reference) and plotBlast.py C (log.cellBlastFoam present); (b) idn copied with cp
# -al to I2, plotIndentation.py I2. Expected: the original's postProcessing/planeWave/0/{reference.dat,+sidecar,
# measures.dat,solidMeasures.dat}, blastSummary.dat, figures, results.md unchanged (md5); changed through the shared inode
# = DATALOSS (and the original's reference then refused against its sidecar, or measured as the copy's).
. "$(dirname "$0")/../lib.sh"
p8; A=$PWD; cp log.cellBlastFoam log.cellBlastFoam.keep; tryt 300 "(0) plotBlast.py in A" /usr/bin/python3 $ROOT/tutorials/blast/plotBlast.py .; echo "   said: $(say 1 | cut -c1-200)"
cd $A; find . -type f ! -name 'log.*' -print0 | sort -z | xargs -0 md5sum > $W/mA; cd $W; cp -al $A $W/C; cd $W/C
tryt 300 "(a) planeWave -Z 40e-6 in the cp -al copy" planeWave -case . -Z 40e-6; echo "   said: $(say 1 | cut -c1-200)"
tryt 300 "(a) plotBlast.py in the copy" /usr/bin/python3 $ROOT/tutorials/blast/plotBlast.py .; echo "   said: $(say 1 | cut -c1-200)"
cd $A; echo "   A: $(md5sum -c $W/mA 2>/dev/null | grep -v ': OK$' | tr '\n' ' ' | cut -c1-400)"; ok_ postProcessing/planeWave/0/reference.dat; echo "   A's reference header: $(sed -n 1p postProcessing/planeWave/0/reference.dat | cut -c1-150)"
cd $W; idn; I=$PWD; pi; find . -type f ! -name 'log.*' -print0 | sort -z | xargs -0 md5sum > $W/mI; cd $W; cp -al $I $W/I2; cd $W/I2; pi; cd $I; echo "   I: $(md5sum -c $W/mI 2>/dev/null | grep -v ': OK$' | tr '\n' ' ' | cut -c1-300) (results.md and indentation.png rewritten with the same content would show as OK)"; stat -c '%n %h' results.md indentation.png | tr '\n' ' '; echo
