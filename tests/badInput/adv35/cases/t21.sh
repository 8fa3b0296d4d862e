#!/bin/bash
# t21: pulseStudy: overpressure negative in pulseStudyDict
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/ps"; cp -r "$ROOT/tutorials/blast/pulseStudy"/system "$W/ps"; cd "$W/ps"; sed -i 's/^overpressure .*/overpressure (-10e6 30e6);/' system/pulseStudyDict
timeout 60 pulseStudy 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
