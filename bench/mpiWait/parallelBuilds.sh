#!/bin/bash
# Two builds' 2-rank results through the pulse's arrival compared (issue
# 18 item 5, branch eff18d: a change of the solid's element ownership
# changes the order of the 2-rank partial sums, i.e. round-off only).
#
#   bench/mpiWait/parallelBuilds.sh DIR BASE NEW
#       DIR   scratch folder (created; must not exist)
#       BASE, NEW  two builds: copies of a worktree's
#             platforms/linux64GccDPInt32Opt (bin/, lib/), e.g. main's
#             build copied before a branch's rebuild
#     prepares, with this worktree's tools, the cases of
#     tests/blast/parallel.sh parts 1 and 3:
#       - short: the axisymmetric preview on the short column to 16 ns
#         (tests/blast/shortColumn.sh), split at y = 4 um;
#       - q3D: the 3D quarter with the tetrahedral 20 um box to 12 ns
#         (Allrun -tet ...), decomposed (2 1 1);
#     runs each on 2 ranks with BASE's and NEW's cellBlastFoam (BASE's
#     or NEW's bin and lib first in PATH and LD_LIBRARY_PATH), q3D also
#     serial with NEW's, and compares (tests/blast/compareRestart.py
#     --h5 --tol 1e-9: the largest differences per log and solid.h5):
#     q3D serial against each 2-rank run, and BASE's 2-rank runs against
#     NEW's. NICENESS=N: the runs at nice -n N (default 10).
set -euo pipefail
[ $# -eq 3 ] || { sed -n 2,22p "$0"; exit 1; }
dir=$1; base=$2; new=$3
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/etc/bashrc"
. "$root/tests/lib/splitAtPlane.sh"
nice=${NICENESS:-10}
for b in "$base" "$new"
do
    [ -x "$b/bin/cellBlastFoam" ] && [ -d "$b/lib" ] || {
        echo "parallelBuilds.sh: $b has no bin/cellBlastFoam and lib/" >&2
        exit 1
    }
done
base=$(cd "$base" && pwd); new=$(cd "$new" && pwd)
[ ! -e "$dir" ] || { echo "parallelBuilds.sh: $dir exists" >&2; exit 1; }
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
compare=$root/tests/blast/compareRestart.py

# run BUILD CASEDIR [-parallel]: cellBlastFoam of BUILD in CASEDIR
run()
{
    local build=$1 c=$2
    shift 2
    (
        export PATH=$build/bin:$PATH
        export LD_LIBRARY_PATH=$build/lib:$LD_LIBRARY_PATH
        cd "$c"
        echo "== $c: $(date -u '+%F %H:%M UTC'), $(command -v cellBlastFoam), load $(cut -d' ' -f1-3 /proc/loadavg)"
        if [ "${1:-}" = -parallel ]
        then
            nice -n "$nice" mpirun -np 2 --bind-to none -x PATH \
                -x LD_LIBRARY_PATH cellBlastFoam -parallel \
                > log.cellBlastFoam 2>&1
        else
            nice -n "$nice" cellBlastFoam > log.cellBlastFoam 2>&1
        fi || { tail -20 log.cellBlastFoam; exit 1; }
        echo "time steps: $(grep -c '^Time =' log.cellBlastFoam)"
        grep '^Solid: .*evaluated for the output' log.cellBlastFoam || true
    )
}

# The short column, split at y = 4 um
bash "$root/tests/blast/shortColumn.sh" "$dir/short" writeControl timeStep \
    writeInterval 25
s=$dir/short/axisymmetricPreview
splitAtPlane "$s" y 4e-6
(cd "$s" && decomposePar > log.decompose 2>&1) \
    || { tail "$s/log.decompose"; exit 1; }

# The 3D quarter, tetrahedral 20 um box, decomposed (2 1 1)
q=$dir/q3D/quarter3D
python3 -m neuronFsi.scratch "$root/tutorials/blast/quarter3D" "$q" \
    0.orig constant system Allrun --ignore polyMesh '*.msh'
(cd "$q" && PROJECT_DIR=$root ./Allrun -tet -box 20e-6 -h 0.6e-6 -far 2e-6 \
    -growth 5e-6 -cell 1.4e-6 -endTime 1.2e-8 -noPlots -noRun \
    > log.prepare 2>&1) || { tail -20 "$q/log.prepare"; exit 1; }
for e in writeControl:timeStep writeInterval:200
do
    foamDictionary -entry "${e%%:*}" -set "${e#*:}" \
        "$q/system/controlDict" > /dev/null
done
cp -r "$dir/q3D" "$dir/q3Dserial"
(cd "$q" && decomposePar > log.decompose 2>&1) \
    || { tail "$q/log.decompose"; exit 1; }

for c in short q3D
do
    cp -r "$dir/$c" "$dir/${c}Base"
    mv "$dir/$c" "$dir/${c}New"
done
run "$base" "$dir/shortBase/axisymmetricPreview" -parallel
run "$new" "$dir/shortNew/axisymmetricPreview" -parallel
run "$base" "$dir/q3DBase/quarter3D" -parallel
run "$new" "$dir/q3DNew/quarter3D" -parallel
run "$new" "$dir/q3Dserial/quarter3D"

status=0
echo "== short column, 2 ranks: BASE against NEW"
/usr/bin/python3 "$compare" "$dir/shortBase/axisymmetricPreview" \
    "$dir/shortNew/axisymmetricPreview" --h5 --tol 1e-9 || status=1
for b in Base New
do
    echo "== 3D quarter: serial against 2 ranks of ${b^^}"
    /usr/bin/python3 "$compare" "$dir/q3Dserial/quarter3D" \
        "$dir/q3D$b/quarter3D" --h5 --tol 1e-9 || status=1
done
echo "== 3D quarter, 2 ranks: BASE against NEW"
/usr/bin/python3 "$compare" "$dir/q3DBase/quarter3D" "$dir/q3DNew/quarter3D" \
    --h5 --tol 1e-9 || status=1
exit $status
