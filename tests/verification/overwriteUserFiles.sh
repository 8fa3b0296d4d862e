#!/bin/bash
# reliability.overwriteUserFiles (adv41 q17, fix19w): -overwrite moves the
# function objects' folders postProcessing/<name>/<time>/ of an earlier run
# aside and removes them at its first write. In a folder no commit marker
# records (a run or restart killed before its first commit), a file used
# to be taken for the run's log if it was empty, an OpenFOAM file or began
# with '#': a user's "# My analysis" notes.md was removed, exit 0. Real
# runs killed by SIGKILL before their first commit, for cellBlastFoam (a
# fresh run, a restart) and rhoRiemannFoam (a fresh run with probes):
#   - with the user's notes.md in the killed run's folder, -overwrite exits
#     non-zero naming it, and every file of the case is unchanged;
#   - the killed run's own logs alone (header-only or empty) are the run's:
#     once notes.md is moved out, -overwrite runs (exit 0).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$root/tests/lib/checks.sh"
md() { printf '# My analysis of %s\n\nThe peak at 1.2 ns is real; see plot.\n' "$1"; }
# every file but the logs and the killed run's stale lock (.runLock, which
# the next run takes over and removes at its end)
sums() { caseSums 'log.*' .runLock; }
set_() { sed -i "s/^$1 .*/$1 $2;/" system/controlDict; }
# killAfter FILE APP...: run APP, SIGKILL it once FILE exists (before the
# first write time), and check that nothing was committed
killAfter() {
    local f=$1; shift
    "$@" > log.killed 2>&1 & local p=$!
    waitFor 120 test -s "$f" || waitFor 5 test -e "$f"
    kill -KILL $p; wait $p 2>/dev/null
}
# refusedThenRuns LABEL NOTE APP...: -overwrite refused naming NOTE, the
# case unchanged; with NOTE moved out, -overwrite runs
refusedThenRuns() {
    local label=$1 note=$2; shift 2
    sums > ../before.md5
    local status=0
    "$@" -overwrite > log.refused 2>&1 || status=$?
    check "$label: -overwrite refused (exit $status), naming $note" \
        "[ $status -ne 0 ] && [ $status -lt 124 ] && grep -q -- '$note' log.refused \
         && grep -q 'hold files the runs of this case did not write' log.refused"
    check "$label: every file of the case unchanged, $note kept" \
        "sums | cmp -s - ../before.md5 && grep -q 'My analysis' $note"
    mv "$note" ../note.md
    status=0
    "$@" -overwrite > log.overwrite 2>&1 || status=$?
    check "$label: the killed run's own logs alone: -overwrite runs (exit $status)" \
        "[ $status -eq 0 ] && grep -q '^End' log.overwrite"
}

# cellBlastFoam: a fresh run killed before its first commit (adv41 q17 f)
cp -r "$root/tests/fsi/pulseLayer" "$work/blast"
cd "$work/blast"
blockMesh > log.blockMesh 2>&1
# (a first write 500 steps away: the whole 8 ns run took 0.2 s once the
# solid's pass got faster, and the kill came after its first write)
set_ endTime 8e-8; set_ writeInterval 4e-8
killAfter postProcessing/solidProbes/0/solidProbes.dat cellBlastFoam
check "cellBlastFoam killed before its first write" "[ ! -e 4e-08 ] && [ -d postProcessing/fsi/0 ]"
md f > postProcessing/solidProbes/0/notes.md
set_ endTime 2e-10; set_ writeInterval 1e-10
refusedThenRuns "cellBlastFoam, fresh run killed" postProcessing/solidProbes/0/notes.md cellBlastFoam

# cellBlastFoam: a restart killed before its first commit (adv41 q17 d)
cd "$work" && rm -rf blast && cp -r "$root/tests/fsi/pulseLayer" blast && cd blast
blockMesh > log.blockMesh 2>&1
set_ endTime 1e-10; set_ writeInterval 1e-10
cellBlastFoam > log.first 2>&1
set_ endTime 8e-8; set_ writeInterval 4e-8
killAfter postProcessing/fsi/1e-10/coupling.dat cellBlastFoam
check "cellBlastFoam restart killed before its first write" "[ ! -e 4e-08 ] && [ -d postProcessing/fsi/1e-10 ]"
md d > postProcessing/fsi/1e-10/notes.md
set_ startFrom startTime; set_ endTime 2e-10
refusedThenRuns "cellBlastFoam, restart killed" postProcessing/fsi/1e-10/notes.md cellBlastFoam

# rhoRiemannFoam with a probes function object: a fresh run killed
cp -r "$root/tutorials/verification/waterShock50MPa" "$work/fluid"
cd "$work/fluid"
rm -rf constant/polyMesh; cp -r 0.orig 0
blockMesh > log.blockMesh 2>&1 && setRiemannProblem > log.set 2>&1
set_ endTime 1e-6; set_ writeInterval 5e-7
printf 'functions { probes { type probes; fields (p U); probeLocations ((1e-5 0 0)); } }\n' >> system/controlDict
killAfter postProcessing/probes/0/p rhoRiemannFoam
check "rhoRiemannFoam killed before its first write" "[ ! -e 5e-07 ] && [ -d postProcessing/probes/0 ]"
md r > postProcessing/probes/0/notes.md
set_ endTime 5e-9; set_ writeInterval 5e-9
refusedThenRuns "rhoRiemannFoam, fresh run killed" postProcessing/probes/0/notes.md rhoRiemannFoam

exit $fail
