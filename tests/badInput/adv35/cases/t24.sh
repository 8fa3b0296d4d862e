#!/bin/bash
# t24: pulseStudy: thresholds value negative
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/ps"; cp -r "$ROOT/tutorials/blast/pulseStudy"/system "$W/ps"; cd "$W/ps"; sed -i '0,/value       0.21 \[-\];/s//value -0.21 [-];/' system/pulseStudyDict
timeout 60 pulseStudy 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
