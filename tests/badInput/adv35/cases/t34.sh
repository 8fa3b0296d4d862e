#!/bin/bash
# t34: planeWave -except with an unknown measure
. "$(dirname "$0")/../lib.sh"
blastDone; planeWave -Z 20e-6 -dz 50e-9 -check -except peek1ns 2>&1 | tail -2; echo "rc=${PIPESTATUS[0]}"
