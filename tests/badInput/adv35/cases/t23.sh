#!/bin/bash
# t23: pulseStudy: baseOptions with an unknown Allrun option
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/ps"; cp -r "$ROOT/tutorials/blast/pulseStudy"/system "$W/ps"; cd "$W/ps"; sed -i 's/^baseOptions .*/baseOptions (-cel 1e-6);/' system/pulseStudyDict
timeout 60 pulseStudy 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
