#!/bin/bash
# a19 (class 3, two planeWave -inflow at once on one case, and a restart beside planeWave): a blast case with a planeWaveInflow top (iblast, its inflowWave removed); planeWave -inflow 20e-6 started twice at once (the second 0.2 s later): the second refused naming the first? constant/inflowWave whole (its rowsDigest verified by a run)? Then planeWave -inflow 25e-6 -overwrite while a cellBlastFoam of the case runs: refused?
. "$(dirname "$0")/../lib.sh"
iblast; rm -f constant/inflowWave; planeWave $IW > ../log.a 2>&1 & p=$!; sleep 0.2; tryf "second planeWave -inflow at once" planeWave $IW; wait $p; echo "   first: rc=$? $(tail -1 ../log.a | cut -c1-160)"
ls -l constant/inflowWave 2>&1 | awk '{print "   inflowWave", $5, "bytes"}'; iEnd 1e-9; tryf "a run reading inflowWave" cellBlastFoam; rm -rf 1e-09 postProcessing solid
iEnd 6e-9; cellBlastFoam > log.second 2>&1 & p=$!; waitFor 120 test -f 1e-09/.writeCommitted; md5sum constant/inflowWave > ../m
tryf "planeWave -inflow 25e-6 -overwrite during the run" planeWave -inflow 25e-6 -Z 40e-6 -overwrite; echo "   inflowWave during the run: $(md5sum -c ../m 2>&1 | awk '{print $2}')"; kill -TERM $p; wait $p
