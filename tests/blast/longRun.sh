#!/bin/bash
# longRun.sh PULSE: the axisymmetric preview at its default meshes to 150 ns
# (the paper's end time) for a pulse of PULSE s (5, 10, 15 ns), then
# checkLongRun.py (completion, coupling, no drift, sound elements). About
# 1.5 min of CPU each on one core (5-8 min before the 2026-12-02 defaults).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
pulse=$1
work=${TMPDIR:-/tmp}/blastLong.$$
trap 'rm -rf "$work"' EXIT
bash "$here/runPreview.sh" "$work" -pulse "$pulse" -endTime 1.5e-7 \
    -noPlots > "$work.log" 2>&1 || { tail -30 "$work.log"; rm -f "$work.log"; exit 1; }
rm -f "$work.log"
/usr/bin/python3 "$here/checkLongRun.py" "$work/axisymmetricPreview" 1.5e-7
