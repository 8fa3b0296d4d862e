#!/bin/bash
# x42: blast preview Allrun (small options) SIGKILLed (whole group) during blockMesh (polled: log.blockMesh appears), then the same ./Allrun: blockMesh (runApplication, no runStep mark) re-run, or skipped over a partial mesh? said?
. "$(dirname "$0")/../lib.sh"
prev; setsid ./Allrun $PREV -endTime 2e-9 > ../log.a1 2>&1 & p=$!; waitFor 60 test -f log.blockMesh; kill -KILL -- -$p; wait $p 2>/dev/null; sleep 0.5
echo "killed: $(ls log.* | tr '\n' ' '); polyMesh: $(ls constant/polyMesh 2>/dev/null | tr '\n' ' '); log.blockMesh end: $(tail -1 log.blockMesh)"; rm -f .runLock
run 200 ./Allrun $PREV -endTime 2e-9 > ../log.a2 2>&1; echo "exit above"; grep -a -i "already\|error\|refus" ../log.a2 | head -4 | cut -c1-200; tail -1 ../log.a2 | cut -c1-200; ls -d [1-9]* 2>/dev/null | tr '\n' ' '
