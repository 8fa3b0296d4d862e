#!/bin/bash
# t17: calibrateCell: target value nan
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/cal"; cp -r "$ROOT/tutorials/calibration/averageCell"/{system,constant} "$W/cal"; cd "$W/cal"; sed -i 's/value 0.3e-9;/value nan;/' system/calibrationDict
timeout 120 calibrateCell 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
