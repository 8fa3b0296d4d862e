#!/bin/bash
# The Fig. 10 probe's readings on the exact field at several cell sizes
# (issue 17 items 1 and 3; docs/results/blast3D.md, "The interface
# reading in solid::PointProbe"); not a test. For each -cell H: a scratch
# copy of tutorials/blast/quarter3D (inputs only) in DIR/cell<H>, prepared
# by Allrun -noRun -noPlots -cell H -lateral 2e-6 -far 10e-6 -inflow
# 14e-6 -pulse 1.5e-8 -endTime 2e-12 [options], cellBlastFoam for its
# first step (writes the mesh into solid/solid.h5 and the probes' header:
# their elements and the interface reading's weights), then
# bench/blast/probeOvershoot.py on it against the 1D answer DIR/ref1d.npz
# (planeWave's column, 50 nm cells, to 85 ns; written by the first case):
# what each reading gives if the solver were exact.
#
#   bench/blast/probeOvershootExact.sh DIR H... [-- Allrun options...]
#       DIR   scratch folder (created if missing; a DIR/cell<H> must not
#             exist)
#     e.g. bench/blast/probeOvershootExact.sh /tmp/pe 1.0e-6 0.7e-6
set -euo pipefail
[ $# -ge 2 ] || { sed -n 2,18p "$0"; exit 1; }
dir=$1; shift
cells=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do cells+=("$1"); shift; done
[ "${1:-}" = "--" ] && shift
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/etc/bashrc"
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
for h in "${cells[@]}"
do
    c=$dir/cell$h
    [ ! -e "$c" ] || { echo "probeOvershootExact.sh: $c exists" >&2; exit 1; }
    python3 -m neuronFsi.scratch "$root/tutorials/blast/quarter3D" "$c" \
        0.orig constant system Allrun --ignore polyMesh '*.msh'
    (
        cd "$c"
        echo "== -cell $h: $(date -u '+%F %H:%M UTC'), commit $(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet HEAD -- src applications tutorials/blast bench/blast || echo ' (with uncommitted changes)'), load $(cut -d' ' -f1-3 /proc/loadavg)"
        PROJECT_DIR=$root ./Allrun -noRun -noPlots -cell "$h" -lateral 2e-6 \
            -far 10e-6 -inflow 14e-6 -pulse 1.5e-8 -endTime 2e-12 "$@" \
            > log.prepare 2>&1 || { tail -20 log.prepare; exit 1; }
        nice -n 10 cellBlastFoam > log.cellBlastFoam 2>&1 \
            || { tail -20 log.cellBlastFoam; exit 1; }
        grep -m1 "hexahedra\|solid elements" log.cellMesh 2>/dev/null || true
        nice -n 10 /usr/bin/python3 "$here/probeOvershoot.py" . \
            --reference "$dir/ref1d.npz" --refEnd 8.5e-8 --pulse 1.5e-8
    )
done
