#!/bin/bash
# t01: planeWave -Z -1
. "$(dirname "$0")/../lib.sh"
blastDone; planeWave -Z -1 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
