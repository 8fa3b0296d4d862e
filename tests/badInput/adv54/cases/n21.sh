#!/bin/bash
# CASETIMEOUT=900
# n21 (new, class 3/5: a second terminal - the blast restarted while planeWave is still measuring the case; planeWave holds
# no case lock): p8 (finished at 8e-9); planeWave -case . -dz 12.5e-9 (its finer column takes a while) started; 1 s later,
# endTime 12e-9 and cellBlastFoam (startFrom latestTime) started in the same case. Expected: the restart refused while
# planeWave reads (or planeWave says the logs changed under it); planeWave's measures.dat of 8e-9 written beside logs of
# 12e-9 without a word, or a log read while being appended = SILENT; the restart's results whole.
. "$(dirname "$0")/../lib.sh"
p8; planeWave -case . -dz 12.5e-9 > $W/pw.log 2>&1 & p=$!; sleep 1; echo "   planeWave running: $(kill -0 $p 2>/dev/null && echo yes || echo no) | lock: $(head -c 100 .runLock 2>/dev/null | tr '\n' ' ')"
blastEnd 12e-9 1e-9; tryt 600 "cellBlastFoam to 12e-9 while planeWave runs" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250) | planeWave still running at the restart's end: $(kill -0 $p 2>/dev/null && echo yes || echo no)"
wait $p; echo "   planeWave rc $? | $(grep -a -i 'error\|running\|changed\|partial\|in use' $W/pw.log | head -2 | tr '\n' '|' | cut -c1-250) | reference header: $(sed -n 1p postProcessing/planeWave/0/reference.dat | cut -c1-120) | last ref time $(tail -n 1 postProcessing/planeWave/0/reference.dat | awk '{print $1}')"
tryt 300 "planeWave -check after both" planeWave -case . -check -reference postProcessing/planeWave/0/reference.dat; echo "   said: $(say 2 | cut -c1-250)"
