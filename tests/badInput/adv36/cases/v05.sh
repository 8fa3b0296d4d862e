#!/bin/bash
# v05: blast: a killed -overwrite left .<time>.overwritten; then a second -overwrite with a late-refused input (coupling maxIter 0): does the put-back keep both sets?
. "$(dirname "$0")/../lib.sh"
blastDone; contents > ../before; blastEnd 2e-8 1e-8
cellBlastFoam -overwrite > log.ow 2>&1 & p=$!; sleep 1.5; kill -KILL $p; wait $p 2>/dev/null; ls -a | tr '\n' ' '; echo
blastEnd 2e-9 1e-9; setd constant/fsiProperties coupling/maxIter 0
cellBlastFoam -overwrite > log.ow2 2>&1; echo "rc=$?"; grep -a -A3 "FATAL\|overwritten\|put back" log.ow2 | head -8
echo "lost:"; lost ../before; ls -a . solid postProcessing/* | tr '\n' ' '; echo
