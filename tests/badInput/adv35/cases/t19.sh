#!/bin/bash
# t19: calibrateCell: parameter of an unknown region (cytoplasma.C10)
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/cal"; cp -r "$ROOT/tutorials/calibration/averageCell"/{system,constant} "$W/cal"; cd "$W/cal"; sed -i 's/cytoplasm.C10/cytoplasma.C10/' system/calibrationDict
timeout 120 calibrateCell 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
