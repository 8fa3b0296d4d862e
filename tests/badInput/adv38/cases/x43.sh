#!/bin/bash
# x43: blast preview Allrun with -Z 40e-6 -inflow 20e-6 (its 1D column planeWave -inflow runs as a runApplication step) SIGKILLed (whole group) during that planeWave, then the same ./Allrun: the inflow step re-run, or skipped with no or a partial constant/inflowWave? said?
. "$(dirname "$0")/../lib.sh"
prev; O="-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 40e-6 -inflow 20e-6 -endTime 3e-9 -writeInterval 1e-9 -noPlots -noVTK"
setsid ./Allrun $O > ../log.a1 2>&1 & p=$!; waitFor 120 test -f log.planeWave.inflow; sleep 1; kill -KILL -- -$p; wait $p 2>/dev/null; sleep 0.5
echo "killed: $(ls log.* | tr '\n' ' '); inflowWave: $(ls -la constant/inflowWave 2>/dev/null | awk '{print $5}')"; echo "lock: $(lockOf)"
run 200 ./Allrun $O > ../log.a2 2>&1; grep -a -i "already\|error\|refus\|stopped" ../log.a2 | head -4 | cut -c1-300; tail -2 ../log.a2 | cut -c1-200; echo "times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"
