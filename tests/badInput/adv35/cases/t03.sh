#!/bin/bash
# t03: planeWave -probes bogus
. "$(dirname "$0")/../lib.sh"
blastDone; planeWave -Z 20e-6 -dz 50e-9 -probes bogus 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
