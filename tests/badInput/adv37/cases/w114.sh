#!/bin/bash
# w114: blast tutorial Allrun SIGKILLed during cellMesh (its log.cellMesh begun), then the same ./Allrun: cellMesh re-run, or skipped with a missing/partial cell.msh?
. "$(dirname "$0")/../lib.sh"
prev; ./Allrun $PREV -endTime 2e-9 > ../log.a1 2>&1 & p=$!; i=0; until [ -f log.cellMesh ] || [ $i -ge 600 ]; do sleep 0.02; i=$((i+1)); done; kill -KILL $p; killIn $W/c; sleep 0.5
echo "killed: cell.msh $(ls constant/cell.msh 2>/dev/null || echo absent), log.cellMesh $(wc -l < log.cellMesh) lines; running: $(inDir $W/c)"
run 200 ./Allrun $PREV -endTime 2e-9 > ../log.a2 2>&1; tail -1 ../log.a2; grep -a -i "skip\|already\|refus\|error" ../log.a2 | head -4 | cut -c1-250; ls | tr '\n' ' '
