#!/bin/bash
# t39: calibrateCell -work into a folder holding a user's file (the run then fails: unknown peak)
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/cal" "$W/mywork"; echo "user data" > "$W/mywork/notes.txt"; cp -r "$ROOT/tutorials/calibration/averageCell"/{system,constant} "$W/cal"; cd "$W/cal"; sed -i 's/peak endB;/peak endX;/' system/calibrationDict
timeout 200 calibrateCell -work "$W/mywork" 2>&1 | tail -2; echo "rc=${PIPESTATUS[0]}"; ls -la "$W/mywork"; cat "$W/mywork/notes.txt"
