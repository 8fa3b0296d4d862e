#!/bin/bash
# v03: ind: -overwrite with a good input SIGKILLed at 0.5 s (before its first checkpoint), then a restart: message and recovery
. "$(dirname "$0")/../lib.sh"
indDone; contents > ../before; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
cellIndentationFoam -overwrite > log.ow 2>&1 & p=$!; sleep 0.7; kill -KILL $p; wait $p 2>/dev/null
echo "lost:"; lost ../before | wc -l; ls -a postProcessing/indentation | tr '\n' ' '; echo
sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict
cellIndentationFoam > log.r1 2>&1; echo "restart rc=$?"; grep -a -A10 FATAL log.r1 | head -12
