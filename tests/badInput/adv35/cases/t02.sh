#!/bin/bash
# t02: planeWave -dz 0
. "$(dirname "$0")/../lib.sh"
blastDone; planeWave -Z 20e-6 -dz 0 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
