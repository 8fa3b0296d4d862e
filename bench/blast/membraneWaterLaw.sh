#!/bin/bash
# membraneWaterLaw.sh DIR [PULSE] [Allrun options]: the axisymmetric preview
# (a copy in DIR, tests/blast/runPreview.sh) with the membrane given water's
# Mie-Grueneisen law instead of its quadratic law (paper eq. 2), run to
# 150 ns, then planeWave -check (DIR/axisymmetricPreview/log.planeWaveCheck).
# Measures how much of the echo near the cell's top the membrane's law
# makes (docs/results/blastPlaneWave.md, "The default at x0.7"). Not a test.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
dir=$1; pulse=${2:-1e-8}; shift; [ $# -gt 0 ] && shift
# DIR.log only over this script's own earlier log (its DIR an earlier
# output of runPreview.sh): a user's file of that name was overwritten
# (adv51 n08 (e)); DIR itself is runPreview.sh's to check
if [ -e "$dir.log" ] && [ "$(cat "$dir/.scratchFolder" 2>/dev/null)" != runPreview.sh ]
then
    echo "membraneWaterLaw.sh: error: $dir.log exists and is not the log" \
        "of an earlier run of this script: give another DIR, or move it" \
        "away. Nothing was removed." >&2
    exit 1
fi
bash "$here/../../tests/blast/runPreview.sh" "$dir" -pulse "$pulse" \
    -noPlots -noVTK -noRun "$@" > "$dir.log" 2>&1
cd "$dir/axisymmetricPreview"
python3 -m neuronFsi.membraneLaw water constant/solidProperties
cellBlastFoam > log.cellBlastFoam 2>&1
status=0
planeWave -case . -check > log.planeWaveCheck 2>&1 || status=$?
grep -v "^#" log.planeWaveCheck
exit $status
