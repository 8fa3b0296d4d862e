#!/bin/bash
# x72: blast run to 1 ns, restarted to 2 ns (log segments */0 and */1e-09), then 2e-09 deleted and a restart from 1e-09 to 2 ns AGAIN (the segment */1e-09 exists from the first restart): accepted? the logs then equal an uninterrupted 2-ns run's (segments put together), no doubled rows, no file like coupling_1e-09.dat beside?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 1e-9 1e-9; cellBlastFoam > log.1 2>&1; latest; blastEnd 2e-9 1e-9; cellBlastFoam > log.2 2>&1; cp -r . ../ref2
rm -rf 2e-09; run 100 cellBlastFoam > log.3 2>&1; tail -1 log.3; fatal log.3 4
sameSeries ../ref2; find postProcessing -type f | sort | tr "\n" " "
