#!/bin/bash
# CASETIMEOUT=900
# n31 (new, class 2/1: n14's hard-linked copy with planeWave -inflow, which writes an INPUT of the run,
# constant/inflowWave): ibd (a preview with a planeWaveInflow top at 20 um, finished at 2e-9) copied with cp -al to C; in
# C `planeWave -case . -inflow 20e-6 -endTime 8e-9 -overwrite` (a longer wave for a longer run); then the ORIGINAL's
# constant/inflowWave (md5) and the original's restart to 3e-9. Expected: the original's inflowWave unchanged (the copy
# writes its own file); changed through the shared inode = DATALOSS (and the original's restart then refused, or run on
# the copy's wave = SILENT).
. "$(dirname "$0")/../lib.sh"
ibd; A=$PWD; md5sum constant/inflowWave > $W/mA; stat -c '%h links' constant/inflowWave; cd $W; cp -al $A $W/C; cd $W/C; stat -c '%h links after cp -al' constant/inflowWave
tryt 300 "(a) planeWave -inflow 20e-6 -endTime 8e-9 -overwrite in the cp -al copy" planeWave -case . -inflow 20e-6 -endTime 8e-9 -overwrite; echo "   said: $(say 2 | cut -c1-250)"
cd $A; echo "   the original's inflowWave: $(md5sum -c $W/mA 2>&1 | sed 's/.*: //') | links now $(stat -c %h constant/inflowWave)"
rs; rm -f .runLock; tryt 300 "(b) the original's restart to 3e-9" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300)"
