#!/bin/bash
# t20: calibrateCell: meshSizeFactor 0
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/cal"; cp -r "$ROOT/tutorials/calibration/averageCell"/{system,constant} "$W/cal"; cd "$W/cal"; sed -i 's/^meshSizeFactor .*/meshSizeFactor 0;/' system/calibrationDict
timeout 120 calibrateCell 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
