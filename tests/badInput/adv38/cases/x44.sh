#!/bin/bash
# x44: blast preview Allrun (small options, with the plots: its last step planeWave) SIGKILLed (whole group) during that last planeWave, then the same ./Allrun: planeWave re-run, or skipped with partial postProcessing/planeWave tables and exit 0?
. "$(dirname "$0")/../lib.sh"
prev; O="-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 20e-6 -endTime 4e-9 -writeInterval 1e-9 -noVTK"
setsid ./Allrun $O > ../log.a1 2>&1 & p=$!; waitFor 200 test -f log.planeWave; sleep 0.3; kill -KILL -- -$p; wait $p 2>/dev/null; sleep 0.5
echo "killed: $(ls log.* | tr '\n' ' '); planeWave: $(ls postProcessing/planeWave 2>/dev/null | tr '\n' ' ')"; rm -f .runLock
run 200 ./Allrun $O > ../log.a2 2>&1; echo "second: exit above"; grep -a -i "already\|error\|refus\|stopped" ../log.a2 | head -4 | cut -c1-250; echo "planeWave now: $(ls postProcessing/planeWave 2>/dev/null | tr '\n' ' ')"; ls *.png 2>/dev/null
