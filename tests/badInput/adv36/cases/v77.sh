#!/bin/bash
# v77: ind: -overwrite SIGKILLed at 0.3 s (before its first checkpoint), then a restart: does its message name the six .<name>.overwritten files kept aside?
. "$(dirname "$0")/../lib.sh"
indDone; contents > ../before; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
cellIndentationFoam -overwrite > log.ow 2>&1 & p=$!; sleep 0.3; kill -KILL $p; wait $p 2>/dev/null; echo "lost: $(lost ../before | wc -l)"; ls -a postProcessing/indentation | tr '\n' ' '; echo
sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict
cellIndentationFoam > log.r1 2>&1; echo "restart rc=$?"; grep -a -A10 FATAL log.r1 | grep -v "^$" | head -10 | cut -c1-300; echo "message names .overwritten: $(grep -ac overwritten log.r1)"
