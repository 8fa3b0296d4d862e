#!/bin/bash
# k53 (class 5/1, checkQuarterRun.sh on a restarted parallel quarter): q restarted to 3e-9 on 2 ranks (two segments in every log), reconstructed, endTime 3e-9: checkQuarterRun.sh. Expected: the segments joined (no duplicated or missing rows: the smoke run fails item 1 for its physics, named per assertion), rc non-zero with the failed assertions named; no traceback. (P1b: log.first copied to log.cellBlastFoam, the name the Allrun gives the solver log, which checkLongRun.py reads)
. "$(dirname "$0")/../lib.sh"
q; latest; qEnd 3e-9; tryt 300 "restart to 3e-9" mpirun -np 2 cellBlastFoam -parallel; (cat log.first; cat $W/try.log) > log.cellBlastFoam; timeout 300 reconstructPar > $W/rp.log 2>&1; echo "   reconstructPar rc=$? times $(ls -d [0-9]* | tr '\n' ' ')"
tryt 600 "checkQuarterRun on the restarted run" bash $ROOT/tests/blast/checkQuarterRun.sh .; grep -a -i 'FAIL\|ok \|Traceback\|error' $W/try.log | head -8 | cut -c1-180 | sed 's/^/   /'
