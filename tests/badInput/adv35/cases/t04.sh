#!/bin/bash
# t04: planeWave -inflow 30e-6 above -Z 20e-6
. "$(dirname "$0")/../lib.sh"
blastDone; planeWave -inflow 30e-6 -Z 20e-6 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
