#!/bin/bash
# t47: planeWave on an indentation case
. "$(dirname "$0")/../lib.sh"
indDone; planeWave 2>&1 | tail -2; echo "rc=${PIPESTATUS[0]}"
