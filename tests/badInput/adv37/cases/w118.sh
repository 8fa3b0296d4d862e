#!/bin/bash
# w118: adv36 v01/v66 with the CURRENT advice: blast -overwrite (maxCo 0.5, to 2e-8) SIGKILLed before its first write, then the loop the restart's message gives run verbatim, maxCo put back, restart to 3 ns: every earlier result back and the restart continues them?
. "$(dirname "$0")/../lib.sh"
blastDone; snap ../before; cp -r postProcessing ../ppOld; sed -i 's/^maxCo .*/maxCo 0.5;/' system/controlDict; blastEnd 2e-8 1e-8
cellBlastFoam -overwrite > log.ow 2>&1 & p=$!; i=0; until ls -a | grep -q overwritten || [ $i -ge 400 ]; do sleep 0.05; i=$((i+1)); done; sleep 0.3; kill -KILL $p; wait $p 2>/dev/null; echo "killed at $(grep -a '^Time = ' log.ow | tail -1); committed: $(ls -d 1e-08 2>/dev/null || echo none)"
latest; sed -i 's/^maxCo .*/maxCo 0.9;/' system/controlDict; blastEnd 3e-9 1e-9; cellBlastFoam > log.r1 2>&1; echo "restart rc=$?"; grep -a -c "find . -depth -name" log.r1
find . -depth -name '.*.overwritten' | while read -r p; do n=${p##*/}; t=${p%/*}/${n#.}; t=${t%.overwritten}; rm -rf "$t"; mv "$p" "$t"; done
echo "after the loop, gone: $(gone ../before | tr '\n' ' ')"; run 120 cellBlastFoam > log.r2 2>&1; fatal log.r2 4; tail -1 log.r2; echo "coupling.dat rows: old $(wc -l < ../ppOld/fsi/0/coupling.dat), now in 0/ $(wc -l < postProcessing/fsi/0/coupling.dat)"
