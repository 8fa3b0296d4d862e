#!/bin/bash
# s10: blast Allrun preparation with -h 1e-9 (fluid mesh size)
. "$(dirname "$0")/../lib.sh"
timeout 60 bash "$ROOT/tests/blast/runPreview.sh" "$W/p" -h 1e-9 -far 2e-6 -cell 0.5e-6 -Z 20e-6 -noRun > log 2>&1; rc=$?; tail -4 log; echo "rc=$rc"
