#!/bin/bash
# t36: planeWave -Z different from the case's column (40e-6 on a 20e-6 case)
. "$(dirname "$0")/../lib.sh"
blastDone; planeWave -Z 40e-6 -dz 50e-9 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
