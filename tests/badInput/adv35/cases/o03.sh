#!/bin/bash
# o03: ind: -overwrite over a finished case, new run killed after 0.3 s
. "$(dirname "$0")/../lib.sh"
indDone; cp -r postProcessing ../pp.before; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
cellIndentationFoam -overwrite > log.new 2>&1 & p=$!; sleep 0.5; kill -9 $p; wait $p; echo "killed rc=$?"
ls -la postProcessing/indentation; wc -l postProcessing/indentation/*.dat
