#!/bin/bash
# CASETIMEOUT=600
# n11 (new, class 2/5: a blast restarted from an earlier time, as a user redoes the last interval): bd (finished at 2e-9,
# writes every 1e-9): (a) 2e-09 removed (rm -r), startFrom latestTime, endTime 2e-9: the run redoes 1e-9..2e-9; then
# planeWave -check and the restart's logs against an uninterrupted run's (the probe log bitwise?); (b) with 2e-09 kept,
# startFrom startTime; startTime 1e-9 (controlDict): refused (results after 1e-9 exist) or redone (the log and marker
# consistent?). Expected: (a) the same logs as the uninterrupted run, measured; (b) refused naming 2e-09 (or -overwrite),
# never a log mixing two runs' rows that is measured.
. "$(dirname "$0")/../lib.sh"
bd; cp postProcessing/fluidProbes/0/p $W/p.ref; cp -a . $W/b0; rm -rf 2e-09; latest; rm -f .runLock; tryt 300 "(a) 2e-09 removed, restart from 1e-09" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | p log $(cmp -s postProcessing/fluidProbes/0/p $W/p.ref && echo 'bitwise the run' || echo DIFFERS) | times $(ls -d [0-9]* | tr '\n' ' ')"
tryt 300 "(a) planeWave -check" planeWave -case . -check; grep -a 'peak1ns' $W/try.log | head -1 | cut -c1-150
cd $W; rm -rf blast; cp -a b0 blast; cd blast; sed -i 's/^startTime .*/startTime 1e-9;/' system/controlDict; rm -f .runLock; tryt 300 "(b) startFrom startTime, startTime 1e-9, 2e-09 kept" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250) | p log $(cmp -s postProcessing/fluidProbes/0/p $W/p.ref && echo 'bitwise the run' || echo DIFFERS) | times $(ls -d [0-9]* | tr '\n' ' ') | aside $(ls -d .*overwritten* 2>/dev/null | tr '\n' ' ')"
tryt 300 "(b) planeWave -check" planeWave -case . -check; grep -a 'peak1ns' $W/try.log | head -1 | cut -c1-150
