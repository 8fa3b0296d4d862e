#!/bin/bash
# v66: blast: -overwrite with another input (maxCo 0.5) SIGKILLed after about 5 ns but before its first write; then the restart's advice (rename the times back) followed, maxCo put back to 0.9, restart: does it continue the old times with the killed run's logs and solid.h5?
. "$(dirname "$0")/../lib.sh"
blastDone; cp -r postProcessing ../ppOld; cp solid/solid.h5 ../solidOld.h5; sed -i 's/^maxCo .*/maxCo 0.5;/' system/controlDict; blastEnd 2e-8 1e-8
cellBlastFoam -overwrite > log.ow 2>&1 & p=$!; sleep 3; kill -KILL $p; wait $p 2>/dev/null; grep -a "^Time = " log.ow | tail -1
for d in .*.overwritten; do t=${d#.}; mv "$d" "${t%.overwritten*}"; done; sed -i 's/^maxCo .*/maxCo 0.9;/' system/controlDict; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9
cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A6 FATAL log.r | head -8 | cut -c1-400
cmp -s solid/solid.h5 ../solidOld.h5 && echo "solid.h5 is the old run's" || echo "solid.h5 is not the old run's"
for f in postProcessing/fsi/0/coupling.dat; do echo "coupling.dat rows now $(wc -l < $f), old $(wc -l < ../ppOld/fsi/0/coupling.dat)"; done
