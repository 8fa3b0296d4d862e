#!/bin/bash
# Where the ranks of a parallel cellBlastFoam run wait (issue 18 item 5):
# the tutorial's 3D quarter (tutorials/blast/quarter3D) prepared on NP
# ranks to END seconds in a scratch copy, run under the mpiWait preload
# library (bench/mpiWait/mpiWait.C, built into DIR), then summary.py.
#
#   bench/mpiWait/mpiWait.sh DIR NP END [Allrun options...]
#       DIR  scratch folder (created; must not exist)
#       NP   MPI ranks (2: the summary pairs two ranks)
#       END  endTime [s], e.g. 3e-8
#   NICENESS=N: cellBlastFoam at nice -n N (default 10)
#   BUILD=DIR: another build, a copy of a worktree's
#       platforms/linux64GccDPInt32Opt (its bin and lib put first in PATH
#       and LD_LIBRARY_PATH after etc/bashrc; mpirun passes both), e.g.
#       main's build copied before a branch's rebuild
#
# The cellBlastFoam on PATH after etc/bashrc runs (or BUILD's).
# Prints the loop's CPU split (cellBlastFoam) and summary.py's table;
# DIR/quarter3D/mpiWait.rank<r> hold the call stacks.
set -euo pipefail
[ $# -ge 3 ] || { sed -n 2,21p "$0"; exit 1; }
dir=$1; np=$2; end=$3; shift 3
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/etc/bashrc"
if [ -n "${BUILD:-}" ]; then
    [ -x "$BUILD/bin/cellBlastFoam" ] && [ -d "$BUILD/lib" ] || {
        echo "mpiWait.sh: BUILD=$BUILD has no bin/cellBlastFoam and lib/" >&2
        exit 1
    }
    BUILD=$(cd "$BUILD" && pwd)
    export PATH=$BUILD/bin:$PATH LD_LIBRARY_PATH=$BUILD/lib:$LD_LIBRARY_PATH
fi
[ ! -e "$dir" ] || { echo "mpiWait.sh: $dir exists" >&2; exit 1; }
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
mpicxx -O2 -shared -fPIC -o "$dir/libmpiWait.so" "$here/mpiWait.C" -ldl
c=$dir/quarter3D
python3 -m neuronFsi.scratch "$root/tutorials/blast/quarter3D" "$c" \
    0.orig constant system Allrun --ignore polyMesh '*.msh'
cd "$c"
echo "== $(date -u '+%F %H:%M UTC'), $(command -v cellBlastFoam), load $(cut -d' ' -f1-3 /proc/loadavg)"
PROJECT_DIR=$root ./Allrun -noRun -noPlots -np "$np" -endTime "$end" "$@" \
    > log.prepare 2>&1 || { tail -20 log.prepare; exit 1; }
MPIWAIT_OUT=$c/mpiWait nice -n "${NICENESS:-10}" mpirun -np "$np" \
    --bind-to none -x LD_PRELOAD="$dir/libmpiWait.so" -x MPIWAIT_OUT \
    -x PATH -x LD_LIBRARY_PATH cellBlastFoam -parallel > log.cellBlastFoam 2>&1
steps=$(grep -c '^Time =' log.cellBlastFoam)
echo "time steps: $steps, $(grep '^FSI coupling [a-zA-Z]*:' log.cellBlastFoam)"
grep -E '^    rank [0-9]+: time loop' log.cellBlastFoam
/usr/bin/python3 "$here/summary.py" "$c/mpiWait" --steps "$steps" --top 30
