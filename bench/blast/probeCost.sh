#!/bin/bash
#------------------------------------------------------------------------------
# probeCost.sh OLDLIB DIR [Allrun options]: the blast preview run by the same
# cellBlastFoam with two builds of libfsi.so side by side (started together,
# one per core), so that a change of src/fsi (e.g. the water probes' cellPoint
# sampling, movingMeshProbes) is timed under the same machine load.
#   OLDLIB  a directory holding the libfsi.so to compare with (e.g. a copy of
#           platforms/*/lib/libfsi.so built from the commit before)
#   DIR     scratch directory: DIR/old, DIR/new (new, empty or an earlier
#           output of this script: etc/scratchFolder)
#   options those of tutorials/blast/axisymmetricPreview/Allrun (default
#           -noPlots -endTime 1e-7)
# Prints each run's "CPU time of the time loop" line (mesh motion, fluid,
# solid, other), the load average before and after, and whether the
# postProcessing files of the two runs are byte-identical (cmp).
#------------------------------------------------------------------------------
set -euo pipefail
[ "$#" -ge 2 ] || { sed -n 3,14p "$0" >&2; exit 1; }
here=$(cd "$(dirname "$0")" && pwd)
oldLib=$(cd "$1" && pwd); dir=$2; shift 2
[ -f "$oldLib/libfsi.so" ] || { echo "no libfsi.so in $oldLib" >&2; exit 1; }
[ "$#" -gt 0 ] || set -- -noPlots -endTime 1e-7
. "$here/../../etc/bashrc"

# DIR new, empty or an earlier output of this script (adv51 n01)
. "$here/../../etc/scratchFolder"
scratchFolder probeCost.sh "$dir" "case/@case" "old/@case" "new/@case"
"$here/../../tests/blast/runPreview.sh" "$dir/case" -noRun "$@" > /dev/null
for v in old new
do
    cp -r "$dir/case/axisymmetricPreview" "$dir/$v"
done

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
(cd "$dir/old" && LD_LIBRARY_PATH=$oldLib:$LD_LIBRARY_PATH \
    cellBlastFoam > log.cellBlastFoam 2>&1) &
oldPid=$!
(cd "$dir/new" && cellBlastFoam > log.cellBlastFoam 2>&1) &
newPid=$!
wait $oldPid
wait $newPid
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"

for v in old new
do
    echo "$v: $(grep 'CPU time of the time loop' "$dir/$v/log.cellBlastFoam")"
done
(cd "$dir/old/postProcessing" && find . -type f | sort) | while read -r f
do
    if cmp -s "$dir/old/postProcessing/$f" "$dir/new/postProcessing/$f"
    then
        echo "identical: $f"
    else
        echo "DIFFERENT: $f"
    fi
done
