#!/bin/bash
# a34 (class 2 + decomposePar/reconstructPar): a 2-rank blast to 2 ns, reconstructPar (the case's own 1e-09, 2e-09 too); then a 2-rank -overwrite from 0 with a 30 MPa pulse, SIGTERMed (mpirun) before its first write: everything put back (processor*/ times, the reconstructed times, solid/, postProcessing/), or left moved aside / lost? then a 2-rank restart to 3 ns (refused), the advice followed, the restart again: everything back and continued?
. "$(dirname "$0")/../lib.sh"
pblastDone; run 120 reconstructPar > log.reconstructPar 2>&1 > /dev/null; sums > ../s; echo "   before: $(ls -d [1-9]* processor1/[1-9]* | tr '\n' ' ')"
restart0; sed -i 's/5e7/3e7/g' 0/p processor*/0/p 2>/dev/null; mpirun -np 2 cellBlastFoam -parallel -overwrite > log.ow 2>&1 & p=$!; waitFor 60 bash -c 'ls -a processor0 | grep -q overwritten'; sleep 0.3; kill -TERM $p; wait $p; echo "   -overwrite SIGTERMed: rc=$? | $(grep -a -m2 -i 'put back\|signal\|error\|restor' log.ow | cut -c1-200 | tr '\n' ' ')"
sed -i 's/3e7/5e7/g' 0/p processor*/0/p 2>/dev/null; echo "   after: $(ls -d [1-9]* processor1/[1-9]* 2>/dev/null | tr '\n' ' '); hidden: $(ls -a . processor0 processor1 | grep -c overwritten)"; echo "   changed: $(changed ../s)"
latest; blastEnd 3e-9 1e-9; tryf "2-rank restart to 3 ns" mpirun -np 2 cellBlastFoam -parallel; echo "   processor1 times $(ls -d processor1/[1-9]* | tr '\n' ' ')"
# the restart's advice followed word for word (its find loop in the case), then the 2-rank restart again: every earlier result back, continued?
find . -depth -name '.*.overwritten' | while read -r p; do n=${p##*/}; t=${p%/*}/${n#.}; t=${t%.overwritten}; rm -rf "$t"; mv "$p" "$t"; done
echo "   after the advice: changed: $(changed ../s)"; tryf "2-rank restart to 3 ns after the advice" mpirun -np 2 cellBlastFoam -parallel; echo "   processor1 times $(ls -d processor1/[1-9]* | tr '\n' ' ')"
