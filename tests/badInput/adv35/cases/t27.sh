#!/bin/bash
# t27: solidToFoam -wedgeAngle nan
. "$(dirname "$0")/../lib.sh"
indDone; solidToFoam -wedgeAngle nan postProcessing/indentation/solid.h5 2>&1 | grep -A3 "FATAL\|rror" | head -5; echo "rc=${PIPESTATUS[0]}"
