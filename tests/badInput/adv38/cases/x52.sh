#!/bin/bash
# x52: planeWave after changes a restart may make (endTime, writeInterval in controlDict.allrun) and after a comment added in constant/thermophysicalProperties: accepted (not refused as changed inputs)?
. "$(dirname "$0")/../lib.sh"
blastDone; blastEnd 5e-9 5e-10; sed -i '0,/^FoamFile/s//\/\/ my note: checked 2026-12-04\nFoamFile/' constant/thermophysicalProperties
try "planeWave after endTime and a comment" planeWave -Z 20e-6 -dz 50e-9; ls postProcessing/planeWave
