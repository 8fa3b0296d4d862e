#!/bin/bash
# x64: blast controlDict: writeInterval 1e-8 above the 2-ns run (no write time before the end), and writeInterval equal to endTime: is the end written? a run that writes nothing but its logs, said or exit 0 silently?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 2e-9 1e-8; run 60 cellBlastFoam > log.a 2>&1; tail -1 log.a; fatal log.a 4; echo "times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ') solid.h5 steps: $(h5ls solid/solid.h5 2>/dev/null | wc -l)"; grep -a -i "no write\|will not write\|writeInterval" log.a | head -2
rm -rf [1-9]* solid postProcessing; blastEnd 2e-9 2e-9; run 60 cellBlastFoam > log.b 2>&1; tail -1 log.b; echo "times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"
