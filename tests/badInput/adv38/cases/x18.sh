#!/bin/bash
# x18: blast run to 1 ns, restarted to 2 ns (log segments postProcessing/*/0 and */1e-09), then -overwrite from 0 with 30 MPa to 2 ns: is the old run's 1e-09 segment (50 MPa rows) left beside the new run's postProcessing/*/0? planeWave then reads which?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 1e-9 1e-9; cellBlastFoam > log.1 2>&1; latest; blastEnd 2e-9 1e-9; cellBlastFoam > log.2 2>&1; ls postProcessing/fsi
sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; sed -i 's/50000000/30000000/g' 0/p
run 120 cellBlastFoam -overwrite > log.o 2>&1; tail -1 log.o; fatal log.o 3
for d in postProcessing/*; do echo "$d: $(ls $d | tr '\n' ' ')"; done; echo "aside: $(find . -name '.*overwritten*' | tr '\n' ' ')"
run 100 planeWave -Z 20e-6 -dz 50e-9 > log.pw1 2>&1; cp -r postProcessing/planeWave ../pw1; rm -rf postProcessing/planeWave; mkdir ../old; for d in postProcessing/*/1e-09; do mv $d ../old/$(echo $d | tr / _); done
run 100 planeWave -Z 20e-6 -dz 50e-9 > log.pw2 2>&1; diff -r ../pw1 postProcessing/planeWave > /dev/null && echo "planeWave tables equal with and without the old run's 1e-09 segments" || { echo "planeWave tables DIFFER with the old run's 1e-09 segments left:"; diff ../pw1/0/measures.dat postProcessing/planeWave/0/measures.dat 2>/dev/null | head -4 | cut -c1-200; ls ../pw1; }
