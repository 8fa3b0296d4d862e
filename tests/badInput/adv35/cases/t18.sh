#!/bin/bash
# t18: calibrateCell: target peak label unknown (endX)
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/cal"; cp -r "$ROOT/tutorials/calibration/averageCell"/{system,constant} "$W/cal"; cd "$W/cal"; sed -i 's/peak endB;/peak endX;/' system/calibrationDict
timeout 120 calibrateCell 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
