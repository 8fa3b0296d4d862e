#!/bin/bash
# v78: ind and blast: after a killed -overwrite (before its first commit) the restart's advice 'to start anew over them deliberately, run with -overwrite' followed: are the earlier results (kept only as .<name>.overwritten, never named) then gone?
. "$(dirname "$0")/../lib.sh"
indDone; contents > ../before; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
cellIndentationFoam -overwrite > log.ow 2>&1 & p=$!; sleep 0.3; kill -KILL $p; wait $p 2>/dev/null; echo "ind: lost after the kill: $(lost ../before | wc -l)"
sed -i 's/maxDepthIncrement 0.01e-6/maxDepthIncrement 0.1e-6/' constant/indenterProperties
cellIndentationFoam -overwrite > log.ow2 2>&1; echo "ind: second -overwrite rc=$?; lost now: $(lost ../before | wc -l) of $(wc -l < ../before); left aside: $(ls -a postProcessing/indentation | grep -c overwritten)"
blastDone; contents > ../before; blastEnd 2e-8 1e-8
cellBlastFoam -overwrite > log.ow 2>&1 & p=$!; sleep 1.5; kill -KILL $p; wait $p 2>/dev/null; echo "blast: lost after the kill: $(lost ../before | wc -l)"
blastEnd 2e-9 1e-9; cellBlastFoam -overwrite > log.ow2 2>&1; echo "blast: second -overwrite rc=$?; lost now: $(lost ../before | wc -l) of $(wc -l < ../before); left aside: $(find . -name '.*overwritten*' | wc -l)"
