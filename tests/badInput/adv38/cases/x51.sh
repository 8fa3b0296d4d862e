#!/bin/bash
# x51: planeWave on a 2-rank finished blast (the records only in processor*/<time>/uniform/inputDigests, no root time) after the water's C0 was changed: refused as in the serial case (w50), or compared silently?
. "$(dirname "$0")/../lib.sh"
pblastDone; sed -i 's/^\(\s*C0\s\+\)1450/\11600/' constant/thermophysicalProperties; grep -a "C0" constant/thermophysicalProperties | head -1
run 120 planeWave -Z 20e-6 -dz 50e-9 > log.pw 2>&1; grep -a -i "error\|changed\|record" log.pw | head -3 | cut -c1-300; ls postProcessing/planeWave 2>/dev/null
