#!/bin/bash
# t31: blast Allrun -pulse abc
. "$(dirname "$0")/../lib.sh"
timeout 60 bash "$ROOT/tests/blast/runPreview.sh" "$W/p" -pulse abc -noRun 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
