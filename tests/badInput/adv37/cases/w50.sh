#!/bin/bash
# w50: blast run to 14 ns with C0 1450 (the pulse reaches the probes), then constant/thermophysicalProperties C0 changed to 1600 (after the run), planeWave: compares the run's probes with the 1D answer of another water than the run's, without a word?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 14e-9 7e-9; cellBlastFoam > log.first 2>&1; echo "run rc=$?"; planeWave -case . > log.pw0 2>&1; echo "before rc=$?"; cp -r postProcessing/planeWave ../pw0
sed -i 's/^\( *C0 *\)1450;/\11600;/' constant/thermophysicalProperties; try after planeWave -case .; grep -a -i "thermo\|changed\|differ" $W/try.log | head -3 | cut -c1-200
for f in ../pw0/0/*.dat; do b=$(basename $f); echo "== $b: the reference columns before | after the edit"; paste <(grep -v '^#' $f | awk '{print $1, $4, $6}') <(grep -v '^#' postProcessing/planeWave/0/$b | awk '{print $4, $6}') | head -3; done
