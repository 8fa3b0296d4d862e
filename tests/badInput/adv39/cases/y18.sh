#!/bin/bash
# y18: x43 with the kill right when log.planeWave.inflow appears (no 1 s wait: x43's premise was not met on this machine): the inflow step re-run saying why, or skipped with a partial constant/inflowWave?
. "$(dirname "$0")/../lib.sh"
prev; O="-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 40e-6 -inflow 20e-6 -endTime 3e-9 -writeInterval 1e-9 -noPlots -noVTK"
setsid ./Allrun $O > ../log.a1 2>&1 & p=$!; waitFor 120 test -f log.planeWave.inflow; kill -KILL -- -$p 2>/dev/null || echo "(the Allrun had ended before the kill)"; wait $p 2>/dev/null; sleep 0.5
echo "killed: $(ls log.* | tr '\n' ' '); inflowWave: $(ls -la constant/inflowWave 2>/dev/null | awk '{print $5}')"
run 200 ./Allrun $O > ../log.a2 2>&1; grep -a -i "already\|error\|refus\|stopped\|again" ../log.a2 | head -6 | cut -c1-300; tail -1 ../log.a2; echo "times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' '); inflowWave: $(ls -la constant/inflowWave 2>/dev/null | awk '{print $5}')"
