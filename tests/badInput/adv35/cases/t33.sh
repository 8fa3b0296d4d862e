#!/bin/bash
# t33: planeWave -reference pointing at a garbage file
. "$(dirname "$0")/../lib.sh"
blastDone; echo "garbage 1 2" > ref.dat; planeWave -Z 20e-6 -dz 50e-9 -reference ref.dat 2>&1 | tail -2; echo "rc=${PIPESTATUS[0]}"
