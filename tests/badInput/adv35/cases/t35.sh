#!/bin/bash
# t35: planeWave -endTime negative
. "$(dirname "$0")/../lib.sh"
blastDone; planeWave -Z 20e-6 -dz 50e-9 -endTime -1e-9 2>&1 | tail -2; echo "rc=${PIPESTATUS[0]}"
