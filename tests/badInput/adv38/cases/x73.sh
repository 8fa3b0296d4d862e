#!/bin/bash
# x73: planeWave on an UNCHANGED 2-rank blast run (nothing edited after the run): (a) decomposed (records in processor*/), (b) after reconstructPar (as the quarter3D Allrun does before its planeWave): accepted, or refused naming an input that did not change?
. "$(dirname "$0")/../lib.sh"
pblastDone; run 120 planeWave -Z 20e-6 -dz 50e-9 > log.pw 2>&1; grep -a -i "error" log.pw | head -2 | cut -c1-450
reconstructPar > log.rec 2>&1 || tail -2 log.rec; grep -a "top" 2e-09/uniform/inputDigests | head -3; run 120 planeWave -Z 20e-6 -dz 50e-9 > log.pw2 2>&1; grep -a -i "error" log.pw2 | head -2 | cut -c1-450; ls postProcessing/planeWave 2>/dev/null
