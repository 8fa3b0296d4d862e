#!/bin/bash
# s09: planeWave -dz 1e-12 on a finished blast case
. "$(dirname "$0")/../lib.sh"
blastDone; timeout 60 planeWave -Z 20e-6 -dz 1e-12 > log.pw 2>&1; rc=$?; grep -i -A3 "error\|Traceback" log.pw | head; tail -2 log.pw; echo "rc=$rc"
