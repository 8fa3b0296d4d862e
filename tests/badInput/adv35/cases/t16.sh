#!/bin/bash
# t16: calibrateCell: parameter min > max
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/cal"; cp -r "$ROOT/tutorials/calibration/averageCell"/{system,constant} "$W/cal"; cd "$W/cal"; sed -i 's/min     0.01;/min 30;/' system/calibrationDict
timeout 120 calibrateCell 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
