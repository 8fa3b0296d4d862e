#!/bin/bash
# reliability.overwriteUserLogs (adv42 g10, g35, g36, g37; fix19x): a
# commit marker (<time>/.writeCommitted) records the logs of the function
# objects' folders postProcessing/<name>/<time>/ as the run's, and
# -overwrite removes what the markers record. It recorded EVERY file of
# the folder, so a user's notes.txt or plot.png put there before a
# restart (g10, g35) or while the run went on (g36, g37) was later removed
# by -overwrite, exit 0. Now a commit records only the files our writers
# put there (runLogFiles.H: the name for the folder and its header), and
# -overwrite takes a recorded file as the run's only if its name is a
# log's (a marker of an earlier build recorded them all). For
# cellBlastFoam (serial and 2 ranks) and rhoRiemannFoam (probes):
#   - the user's files in the folder of the run's segment, added between a
#     run and its restart: no marker names them; -overwrite exits
#     non-zero naming them, every file of the case unchanged;
#   - the same with the user's file added while the run goes on (after its
#     first commit; cellBlastFoam, serial);
#   - a marker line of an earlier build naming the user's file as a log:
#     -overwrite refuses naming it;
#   - a file named like a log in another log's folder (coupling.dat in
#     solidProbes/0/, with coupling.dat's header) and a file with a log's
#     name but a user's content (coupling.dat in a segment folder no run
#     wrote): refused, naming them;
#   - the user's files moved out, -overwrite runs (exit 0).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$root/tests/lib/checks.sh"
# every file but the logs and a stale lock
sums() { caseSums 'log.*' .runLock; }
set_() { sed -i "s/^$1 .*/$1 $2;/" system/controlDict; }
# notRecorded LABEL FILE...: no commit marker of the case names the files
notRecorded() {
    local label=$1 re; shift
    re="^log .*/($(IFS='|'; echo "$*"))\$"
    check "$label: no commit marker records the user's files as logs" \
        "[ -n \"\$(ls -d */.writeCommitted processor*/*/.writeCommitted 2>/dev/null)\" ] \
         && ! cat */.writeCommitted processor*/*/.writeCommitted 2>/dev/null | grep -a -q -E '$re'"
}
# refusedThenRuns LABEL "APP..." FILE...: -overwrite refused naming every
# FILE, the case unchanged; the files moved out, -overwrite runs
refusedThenRuns() {
    local label=$1 app=$2 f; shift 2
    set_ startFrom startTime
    sums > ../before.md5
    local status=0
    $app -overwrite > log.refused 2>&1 || status=$?
    local named=1
    for f in "$@"; do grep -q -- "$f" log.refused || named=0; done
    check "$label: -overwrite refused (exit $status), naming $*" \
        "[ $status -ne 0 ] && [ $status -lt 124 ] && [ $named = 1 ] \
         && grep -q 'did not write' log.refused"
    check "$label: every file of the case unchanged, the user's files kept" \
        "sums | cmp -s - ../before.md5"
    rm -rf ../moved; mkdir ../moved
    for f in "$@"; do mv "$f" ../moved/; done
    status=0
    $app -overwrite > log.overwrite 2>&1 || status=$?
    check "$label: the user's files moved out, -overwrite runs (exit $status)" \
        "[ $status -eq 0 ] && grep -q '^End' log.overwrite"
}
blastCase() {
    cd "$work" && rm -rf blast && cp -r "$root/tests/fsi/pulseLayer" blast && cd blast
    blockMesh > log.blockMesh 2>&1
    set_ startFrom latestTime
}

# cellBlastFoam: the user's files in the restart's segment folder and in
# the first run's (g10, g35), added between run and restart
blastCase
set_ endTime 1e-10; set_ writeInterval 1e-10
cellBlastFoam > log.first 2>&1
mkdir -p postProcessing/fsi/1e-10 postProcessing/solidProbes/1e-10
printf 'plain notes of the restart segment\n' > postProcessing/fsi/1e-10/notes.txt
printf '# My analysis\n' > postProcessing/solidProbes/1e-10/notes.md
printf 'png\n' > postProcessing/solidProbes/0/plot.png
set_ endTime 3e-10
cellBlastFoam > log.restart 2>&1
check "cellBlastFoam: the restart with the user's files runs" "grep -q '^End' log.restart && [ -d 3e-10 ]"
notRecorded "cellBlastFoam, restart" notes.txt notes.md plot.png
refusedThenRuns "cellBlastFoam, restart" cellBlastFoam postProcessing/fsi/1e-10/notes.txt \
    postProcessing/solidProbes/1e-10/notes.md postProcessing/solidProbes/0/plot.png

# cellBlastFoam: the user's files written while the run goes on (g36)
blastCase
set_ endTime 6e-10; set_ writeInterval 1e-10
cellBlastFoam > log.first 2>&1 & p=$!
waitFor 120 test -f 1e-10/.writeCommitted
printf 'notes during the run\n' > postProcessing/fsi/0/notes.txt
printf 'png\n' > postProcessing/solidProbes/0/plot.png
wait $p
check "cellBlastFoam: the run with the user's files written during it ends" "grep -q '^End' log.first && [ -d 6e-10 ]"
notRecorded "cellBlastFoam, during the run" notes.txt plot.png
# a marker of an earlier build (no seal), which recorded every file of
# the folder
sed -i '/^seal /d; /^end$/i log 0123456789abcdef 21 postProcessing/fsi/0/notes.txt' 6e-10/.writeCommitted
# a log's name in another log's folder, with that log's header; a log's
# name with the user's content in a segment folder no run wrote
head -3 postProcessing/fsi/0/coupling.dat > postProcessing/solidProbes/0/coupling.dat
mkdir -p postProcessing/fsi/5e-10
printf 'my own coupling table\n' > postProcessing/fsi/5e-10/coupling.dat
refusedThenRuns "cellBlastFoam, during the run" cellBlastFoam postProcessing/fsi/0/notes.txt \
    postProcessing/solidProbes/0/plot.png postProcessing/solidProbes/0/coupling.dat \
    postProcessing/fsi/5e-10/coupling.dat

# cellBlastFoam on 2 ranks: the user's files between run and restart
blastCase
printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmethod simple;\ncoeffs { n (2 1 1); }\n' > system/decomposeParDict
decomposePar > log.decomposePar 2>&1
set_ endTime 1e-10; set_ writeInterval 1e-10
mpirun -np 2 cellBlastFoam -parallel > log.first 2>&1
printf 'plain notes\n' > postProcessing/fsi/0/notes.txt
mkdir -p postProcessing/solidProbes/1e-10
printf 'png\n' > postProcessing/solidProbes/1e-10/plot.png
set_ endTime 3e-10
mpirun -np 2 cellBlastFoam -parallel > log.restart 2>&1
check "cellBlastFoam -parallel: the restart with the user's files runs" \
    "grep -q '^End' log.restart && [ -d processor0/3e-10 ]"
notRecorded "cellBlastFoam -parallel" notes.txt plot.png
refusedThenRuns "cellBlastFoam -parallel" "mpirun -np 2 cellBlastFoam -parallel" \
    postProcessing/fsi/0/notes.txt postProcessing/solidProbes/1e-10/plot.png

# rhoRiemannFoam with probes (g37)
cp -r "$root/tutorials/verification/waterShock50MPa" "$work/fluid"
cd "$work/fluid"
rm -rf constant/polyMesh; cp -r 0.orig 0
blockMesh > log.blockMesh 2>&1 && setRiemannProblem > log.set 2>&1
set_ startFrom latestTime; set_ endTime 5e-9; set_ writeInterval 5e-9
printf 'functions { probes { type probes; fields (p U); probeLocations ((1e-5 0 0)); } }\n' >> system/controlDict
rhoRiemannFoam > log.first 2>&1
printf 'plain notes\n' > postProcessing/probes/0/notes.txt
set_ endTime 1e-8
rhoRiemannFoam > log.restart 2>&1
check "rhoRiemannFoam: the restart with the user's file runs" "grep -q '^End' log.restart && [ -d 1e-08 ]"
notRecorded "rhoRiemannFoam" notes.txt
set_ endTime 5e-9
refusedThenRuns "rhoRiemannFoam" rhoRiemannFoam postProcessing/probes/0/notes.txt

exit $fail
