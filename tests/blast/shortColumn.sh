#!/bin/bash
# shortColumn.sh DIR [ENTRY VALUE]...: the axisymmetric preview on a short
# water column (20 um, coarse far field, to 16 ns; the restart tests)
# prepared, not run, in DIR/axisymmetricPreview, with the given entries of
# system/controlDict set. Quiet unless it fails.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
dir=$1; shift
log=$(mktemp)
trap 'rm -f "$log"' EXIT
bash "$here/runPreview.sh" "$dir" -h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 \
    -Z 20e-6 -endTime 1.6e-8 -noPlots -noRun > "$log" 2>&1 \
    || { cat "$log"; exit 1; }
while [ "$#" -ge 2 ]
do
    foamDictionary -entry "$1" -set "$2" \
        "$dir/axisymmetricPreview/system/controlDict" > /dev/null
    shift 2
done
