#!/bin/bash
# w113: blast tutorial Allrun (small options, 8 ns) SIGKILLed while its solver runs, then the same ./Allrun again: does it continue the solver, refuse, or skip it (its log exists) and report success with partial results?
. "$(dirname "$0")/../lib.sh"
prev; ./Allrun $PREV -endTime 8e-9 > ../log.a1 2>&1 & p=$!; i=0; until ls -d 2e-09 >/dev/null 2>&1 || [ $i -ge 600 ]; do sleep 0.1; i=$((i+1)); done; kill -KILL $p; killIn $W/c; sleep 1
echo "killed: times $(ls -d [1-9]* 2>/dev/null | tr '\n' ' '); still running: $(inDir $W/c)"
run 200 ./Allrun $PREV -endTime 8e-9 > ../log.a2 2>&1; tail -1 ../log.a2; grep -a -i "skip\|already\|refus\|error\|continu" ../log.a2 | head -4 | cut -c1-250; echo "times now: $(ls -d [1-9]* | tr '\n' ' ')"
