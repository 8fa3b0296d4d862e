#!/bin/bash
# t22: pulseStudy: duration empty list
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/ps"; cp -r "$ROOT/tutorials/blast/pulseStudy"/system "$W/ps"; cd "$W/ps"; sed -i 's/^duration .*/duration ();/' system/pulseStudyDict
timeout 60 pulseStudy 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
