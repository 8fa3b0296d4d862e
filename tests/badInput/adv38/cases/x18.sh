#!/bin/bash
# x18: blast run to 1 ns, restarted to 2 ns (log segments postProcessing/*/0 and */1e-09), then -overwrite from 0 with 30 MPa to 2 ns: is the old run's 1e-09 segment (50 MPa rows) left beside the new run's postProcessing/*/0? planeWave then reads which?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 1e-9 1e-9; cellBlastFoam > log.1 2>&1; latest; blastEnd 2e-9 1e-9; cellBlastFoam > log.2 2>&1; ls postProcessing/fsi
sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; sed -i 's/5e7/3e7/g' 0/p
run 120 cellBlastFoam -overwrite > log.o 2>&1; tail -1 log.o; fatal log.o 3
for d in postProcessing/*; do echo "$d: $(ls $d | tr '\n' ' ')"; done; echo "aside: $(find . -name '.*overwritten*' | tr '\n' ' ')"
