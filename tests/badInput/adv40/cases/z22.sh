#!/bin/bash
# z22: power-loss shapes in the Allrun's records: the preview Allrun (-noRun, small options) done, then (a) .allrunOptions all NUL bytes, (b) .allrunOptions empty, (c) log.cellMesh.status all NUL; the same ./Allrun again each time: refused naming the damaged record (or re-run from a clean state), never a traceback or a silent skip?
. "$(dirname "$0")/../lib.sh"
prev; run 200 ./Allrun $PREV -endTime 2e-9 -noRun > ../log.a0 2>&1; echo "prepared: $(ls -a | grep -c '^log\.') logs, record: $(head -c 100 .allrunOptions | tr '\n' '|')"; cp -r $W/c $W/keep
ag() { run 200 ./Allrun $PREV -endTime 2e-9 -noRun > ../log.$1 2>&1; echo "   $1: $(grep -a -i -m3 "already\|error\|refus\|Traceback\|record\|damaged\|allrunOptions" ../log.$1 | cut -c1-220 | tr '\n' '|')"; }
nul .allrunOptions; ag a
cd $W; rm -rf c; cp -r keep c; cd c; : > .allrunOptions; ag b
cd $W; rm -rf c; cp -r keep c; cd c; ls log.*status | head -3; nul log.cellMesh.status; ag c; echo "   cell.msh same as before: $(cmp -s constant/cell.msh $W/keep/constant/cell.msh && echo yes || echo no)"
