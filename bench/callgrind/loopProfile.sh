#!/bin/bash
# Instruction counts of cellBlastFoam's time loop, serial against 2 ranks
# (issue 18 item 5, branch eff18e): where the second rank's extra work is,
# measured with a load-independent measure (callgrind's Ir) on a shared
# machine. The tutorial's 3D quarter (tutorials/blast/quarter3D) is
# prepared to END seconds in DIR/s (serial) and DIR/p (NP ranks) as
# bench/mpiWait/mpiWait.sh prepares it, then cellBlastFoam runs under
#   valgrind --tool=callgrind --collect-atstart=no
#       --toggle-collect=Foam::fluidSolidInteraction::step()
#       --toggle-collect=Foam::fluidSolidInteraction::setDeltaT()
#       --toggle-collect=Foam::fluidSolidInteraction::write(double)
# (the time loop's coupled step, time-step control and per-step output;
# start-up, checkStates and the field writes not counted), serial, then
# mpirun -np NP, and exclusive.py compares them (the per-function table,
# Open MPI's polling counted apart).
#
#   bench/callgrind/loopProfile.sh DIR [END [NP]]
#       DIR  scratch folder (created; must not exist)
#       END  endTime [s] (default 6e-9: 110 steps, one pass each)
#       NP   ranks (default 2)
#   BUILD=DIR: another build (a copy of a worktree's
#       platforms/linux64GccDPInt32Opt), as for mpiWait.sh
#   VGOPTS="...": more valgrind options (e.g. --cache-sim=yes)
#   NICENESS=N (default 10)
#   CONCURRENT=1: the serial and the parallel run at the same time (the
#       counts are the same; on a shared machine the pair gets more of
#       the cores than one run after the other)
#
# Takes about 50x the native run's CPU time per rank: 110 steps of the
# quarter are about 10 min serial and 10 min on 2 ranks on 2 idle cores.
# Results: DIR/s/quarter3D/cg.serial, DIR/p/quarter3D/cg.rank<r>,
# DIR/exclusive.txt.
set -euo pipefail
[ $# -ge 1 ] || { sed -n 2,29p "$0"; exit 1; }
dir=$1; end=${2:-6e-9}; np=${3:-2}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/etc/bashrc"
if [ -n "${BUILD:-}" ]; then
    [ -x "$BUILD/bin/cellBlastFoam" ] && [ -d "$BUILD/lib" ] || {
        echo "loopProfile.sh: BUILD=$BUILD has no bin/cellBlastFoam and lib/" >&2
        exit 1
    }
    BUILD=$(cd "$BUILD" && pwd)
    export PATH=$BUILD/bin:$PATH LD_LIBRARY_PATH=$BUILD/lib:$LD_LIBRARY_PATH
fi
[ ! -e "$dir" ] || { echo "loopProfile.sh: $dir exists" >&2; exit 1; }
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
vg=(valgrind --tool=callgrind --collect-atstart=no
    "--toggle-collect=Foam::fluidSolidInteraction::step()"
    "--toggle-collect=Foam::fluidSolidInteraction::setDeltaT()"
    "--toggle-collect=Foam::fluidSolidInteraction::write(double)"
    ${VGOPTS:-})
for n in s p
do
    c=$dir/$n/quarter3D
    npOpt=()
    [ $n = s ] || npOpt=(-np "$np")
    python3 -m neuronFsi.scratch "$root/tutorials/blast/quarter3D" "$c" \
        0.orig constant system Allrun --ignore polyMesh '*.msh'
    (cd "$c" && PROJECT_DIR=$root ./Allrun -noRun -noPlots "${npOpt[@]}" \
        -endTime "$end" > log.prepare 2>&1) || { tail -20 "$c/log.prepare"; exit 1; }
done
echo "== $(date -u '+%F %H:%M UTC'), $(command -v cellBlastFoam), load $(cut -d' ' -f1-3 /proc/loadavg)"
serialRun()
{
    cd "$dir/s/quarter3D"
    nice -n "${NICENESS:-10}" "${vg[@]}" \
        --callgrind-out-file="$PWD/cg.serial" \
        cellBlastFoam > log.cellBlastFoam 2>&1
    echo "== serial done $(date -u '+%H:%M UTC'): $(grep -c '^Time =' log.cellBlastFoam) steps"
}
parallelRun()
{
    cd "$dir/p/quarter3D"
    nice -n "${NICENESS:-10}" mpirun -np "$np" --bind-to none -x PATH \
        -x LD_LIBRARY_PATH "${vg[@]}" \
        --callgrind-out-file="$PWD/cg.rank%q{OMPI_COMM_WORLD_RANK}" \
        cellBlastFoam -parallel > log.cellBlastFoam 2>&1
    echo "== $np ranks done $(date -u '+%H:%M UTC'): $(grep -c '^Time =' log.cellBlastFoam) steps"
}
if [ "${CONCURRENT:-0}" = 1 ]
then
    serialRun &
    serialPid=$!
    (parallelRun)
    wait "$serialPid"
else
    (serialRun)
    (parallelRun)
fi
ranks=()
for ((r = 0; r < np; ++r)); do ranks+=("$dir/p/quarter3D/cg.rank$r"); done
/usr/bin/python3 "$here/exclusive.py" "$dir/s/quarter3D/cg.serial" \
    "${ranks[@]}" --top 40 | tee "$dir/exclusive.txt"
