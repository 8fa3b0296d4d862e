#!/bin/bash
# w50: blast run to 2 ns with C0 1450, then thermophysicalProperties C0 changed to 1600 (after the run), planeWave: compares the run's probes with the 1D answer of ANOTHER water than the run's, without a word?
. "$(dirname "$0")/../lib.sh"
blastDone; planeWave -case . > log.pw0 2>&1; echo "before rc=$?"; grep -a -i "arrival\|peak" log.pw0 | head -3 | cut -c1-200
sed -i 's/^\( *C0 *\)1450;/\11600;/' constant/thermophysicalProperties; try after planeWave -case . -overwrite; grep -a -i "arrival\|peak\|thermo\|changed" $W/try.log | head -4 | cut -c1-200
