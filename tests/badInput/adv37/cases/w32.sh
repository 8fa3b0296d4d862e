#!/bin/bash
# w32: ind killed at 2 s, restart.h5 swapped with the one of another case killed at 2 s whose bead radius is 10 um: restart refused?
. "$(dirname "$0")/../lib.sh"
indKilled 2; mkdir -p ../o; cd ..; mv ind mine; indKilled 2 >/dev/null; cd ..; mv ind o2; cd o2; setd constant/indenterProperties radius 10e-6; rm -rf postProcessing; cellIndentationFoam > log.o 2>&1 & p=$!; sleep 2; kill -KILL $p; wait $p 2>/dev/null
cd ../mine; cp ../o2/postProcessing/indentation/restart.h5 postProcessing/indentation/restart.h5; run 120 cellIndentationFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
