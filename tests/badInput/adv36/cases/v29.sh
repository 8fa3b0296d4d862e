#!/bin/bash
# v29: blast: planeWave -inflow on the classic top without -Z, and -inflow 0 / -inflow 1e-3
. "$(dirname "$0")/../lib.sh"
blastDone; for a in "-inflow 15e-6" "-inflow 0" "-inflow 1e-3"; do planeWave $a -dz 50e-9 > log.pw 2>&1; echo "$a rc=$?"; grep -ai error log.pw | head -1 | cut -c1-250; done; ls constant | grep -c inflowWave
