#!/bin/bash
# x50: sweepCase on a case holding a STALE lock (a killed run's, process gone) and one holding a finished run's results: is the stale lock copied into every value's run (each run then takes it over, or refuses 'a lock naming another case')? the table written?
. "$(dirname "$0")/../lib.sh"
indDone; printf 'pid 999999\nhost %s\nexecutable cellIndentationFoam\nstarted 2026-12-01T10:00:00\ncase %s\n' $(hostname) "$PWD" > .runLock
run 250 sweepCase -case . -entry constant/indenterProperties/holdGrowth -values "1.5 1.4" -run "cellIndentationFoam -overwrite" -name g -nProcs 1 -output "F=postProcessing/indentation/peaks.dat:-1:force" > ../log.s 2>&1; grep -a -v "^\s*$" ../log.s | tail -5 | cut -c1-300; echo "lock: $(lockOf)"; ls .. | tr '\n' ' '
