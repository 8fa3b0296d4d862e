#!/bin/bash
# v26: blast: planeWave with -Z written otherwise (2.0e-5), slightly off (2.00001e-5), 5 % off (2.1e-5), negative (-2e-5)
. "$(dirname "$0")/../lib.sh"
blastDone; for z in 2.0e-5 2.00001e-5 2.1e-5 -2e-5; do planeWave -Z=$z -dz 50e-9 > log.pw 2>&1; echo "-Z $z rc=$?"; grep -ai "error" log.pw | head -2 | cut -c1-300; done
