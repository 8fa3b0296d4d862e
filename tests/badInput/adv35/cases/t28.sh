#!/bin/bash
# t28: solidToFoam -wedgeAngle 360
. "$(dirname "$0")/../lib.sh"
indDone; solidToFoam -wedgeAngle 360 postProcessing/indentation/solid.h5 2>&1 | grep -A3 "FATAL\|rror" | head -5; echo "rc=${PIPESTATUS[0]}"
