#!/bin/bash
# t05: planeWave twice on a finished blast case (second replaces derived output)
. "$(dirname "$0")/../lib.sh"
blastDone; planeWave -Z 20e-6 -dz 50e-9 > l1 2>&1; echo "rc1=$?"; tail -3 l1; planeWave -Z 20e-6 -dz 50e-9 2>&1 | tail -2; echo "rc2=${PIPESTATUS[0]}"
