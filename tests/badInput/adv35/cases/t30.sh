#!/bin/bash
# t30: solidToFoam -region ../evil (path outside)
. "$(dirname "$0")/../lib.sh"
indDone; solidToFoam -region ../evil postProcessing/indentation/solid.h5 2>&1 | grep -A3 "FATAL\|rror" | tail -4; echo "rc=${PIPESTATUS[0]}"; ls .. 
