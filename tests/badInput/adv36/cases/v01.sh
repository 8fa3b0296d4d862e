#!/bin/bash
# v01: blast: -overwrite with a good input SIGKILLed at 1.5 s (before its first write at 1e-8 s), then the restart's advice followed verbatim: is every earlier result back and does the run continue?
. "$(dirname "$0")/../lib.sh"
blastDone; contents > ../before; blastEnd 2e-8 1e-8
cellBlastFoam -overwrite > log.ow 2>&1 & p=$!; sleep 1.5; kill -KILL $p; wait $p 2>/dev/null; echo "killed -overwrite; lost now:"; lost ../before | wc -l
ls -a . solid postProcessing/* | tr '\n' ' '; echo
sed -i 's/^startFrom .*/startFrom latestTime;/' system/controlDict; blastEnd 2e-9 1e-9
cellBlastFoam > log.r1 2>&1; echo "restart rc=$?"; grep -a -A12 FATAL log.r1 | head -14
for d in .*.overwritten; do [ -e "$d" ] || continue; t=${d#.}; mv "$d" "${t%.overwritten*}"; done
echo "after the advice's loop, lost:"; lost ../before | wc -l; ls -a . solid postProcessing/* | tr '\n' ' '; echo
blastEnd 3e-9 1e-9; cellBlastFoam > log.r2 2>&1; echo "restart2 rc=$?"; grep -a -A6 FATAL log.r2 | head -8; grep -a "Continuing\|^End" log.r2 | head -3
