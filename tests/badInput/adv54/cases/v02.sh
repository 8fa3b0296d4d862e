#!/bin/bash
# CASETIMEOUT=900
# v02 (fix19j row "a second script in the first's output folder" (.scratchLock), varied: another script, other spellings
# of the folder, the script killed while its solver goes on): (a) tests/blast/runPreview.sh D (the smoke sizes, -endTime
# 3e-8) in the background; once its solver runs, bench/blast/probeCost.sh <lib dir> D (another script, same folder);
# (b) runPreview.sh D/. and runPreview.sh <D through a symbolic link> while (a)'s first runs; (c) the first runPreview.sh's
# shell SIGKILLed (its solver, which inherited the lock, goes on), then runPreview.sh D -noRun again.
# Expected: every second script refused naming D's lock and the live run, nothing under D removed, the run ends whole.
. "$(dirname "$0")/../lib.sh"
cd $W; O="-h 0.25e-6 -far 2e-6 -cell 0.5e-6 -Z 20e-6 -endTime 3e-8 -writeInterval 1e-9 -noPlots -noVTK"
bash $ROOT/tests/blast/runPreview.sh $W/D $O > $W/log.first 2>&1 & p=$!
for i in $(seq 1 600); do [ -f $W/D/axisymmetricPreview/.runLock ] && break; sleep 0.2; done; sleep 2
echo "   first: alive $(kill -0 $p 2>/dev/null && echo yes || echo no) | D/.scratchLock: $(tr '\n' ' ' < $W/D/.scratchLock 2>/dev/null | cut -c1-150) | times $(ls -d $W/D/axisymmetricPreview/[1-9]* 2>/dev/null | wc -l)"
find $W/D -type f | sort > $W/files0
lib=$(dirname $(find $ROOT/platforms -name libfsi.so | head -n 1)); tryt 120 "(a) probeCost.sh LIB D while runPreview.sh runs" bash $ROOT/bench/blast/probeCost.sh $lib $W/D; echo "   said: $(say 2 | cut -c1-300)"
tryt 120 "(b) runPreview.sh D/." bash $ROOT/tests/blast/runPreview.sh $W/D/. $O; echo "   said: $(say 2 | cut -c1-250)"
ln -s $W/D $W/Dlink; tryt 120 "(b2) runPreview.sh Dlink (a link to D)" bash $ROOT/tests/blast/runPreview.sh $W/Dlink $O; echo "   said: $(say 2 | cut -c1-250)"
echo "   D's files: $(find $W/D -type f | sort | comm -23 $W/files0 - | wc -l) of $(wc -l < $W/files0) gone"
kill -KILL $p; sleep 1; echo "   (c) runPreview.sh's shell killed; solver alive: $(pgrep -f cellBlastFoam > /dev/null && echo yes || echo no)"
tryt 120 "(c) runPreview.sh D -noRun again, the solver still running" bash $ROOT/tests/blast/runPreview.sh $W/D $O -noRun; echo "   said: $(say 2 | cut -c1-300)"
echo "   D's files: $(find $W/D -type f | sort | comm -23 $W/files0 - | wc -l) of $(wc -l < $W/files0) gone"
killIn $W/D; sleep 1
