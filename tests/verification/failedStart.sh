#!/bin/bash
# A new start that fails before it wrote any result leaves nothing that
# blocks the next start, and never removes what was there before it
# (issue 19, classes 2 and 6; adv38 x54: cellIndentationFoam on a full
# disk left an empty force.dat and solid.h5.tmp, and the next start, space
# freed, was refused as "holds results of an earlier run ... -overwrite";
# cellBlastFoam left its function objects' header-only postProcessing/*/0
# folders the same way; src/foamTools/resultGuard.H, cleanNewStart).
# For cellIndentationFoam and cellBlastFoam:
#  - the solid's results file cannot be created (its temporary name,
#    <file>.tmp, is a folder): the run exits non-zero naming the file; no
#    file or folder it made is left, the files that were there (a user's
#    notes beside the outputs, the folder in the way) are unchanged;
#  - that folder removed, the next start runs to its end;
#  - cellIndentationFoam whose first step fails (a nucleus 1000 times
#    stiffer, as tests/verification/resultGuard.sh): the same;
#  - a run that wrote results before it failed (the indentation's first
#    row written, then a force target refused) keeps them: results;
#  - as root (a tmpfs can be mounted): the true full disk, whose message
#    names the free bytes ("No space left on device"), and the next start
#    after space is freed.
set -euo pipefail
. "$(dirname "$0")/../lib/restartTools.sh"
. "$(dirname "$0")/../lib/checks.sh"

# every file and folder of the case (logs and the run lock aside), sorted
paths() { find . ! -name 'log.*' ! -name '.runLock' | sort; }

# failsThenRuns NAME SOLVER BLOCK: BLOCK (a path) is made a folder so that
# the solid's results file cannot be created; the run must fail leaving
# the case as it was; BLOCK removed, the next start runs
failsThenRuns()
{
    local name=$1 solver=$2 block=$3 status=0
    mkdir -p "$block"
    caseSums 'log.*' > "$work/$name.before"
    paths > "$work/$name.paths.before"
    $solver > log.fails 2>&1 || status=$?
    check "$name: exits non-zero naming the file it could not create" \
        "[ $status -ne 0 ] && [ $status -lt 124 ] \
         && grep -q \"cannot create HDF5 file '.*$(basename "$block")'\" log.fails"
    caseSums 'log.*' > "$work/$name.after"
    paths > "$work/$name.paths.after"
    check "$name: nothing it made is left, nothing that was there changed" \
        "cmp -s '$work/$name.before' '$work/$name.after' \
         && cmp -s '$work/$name.paths.before' '$work/$name.paths.after'"
    rmdir "$block"
    status=0
    $solver > log.next 2>&1 || status=$?
    check "$name: the next start runs to its end (not refused over the failed start's files)" \
        "[ $status -eq 0 ] && grep -q '^End' log.next"
}

# cellIndentationFoam: the average cell on the coarse fallback mesh (as
# the bad-input corpus's base case), a one-row table
mkdir "$work/indentation"; cd "$work/indentation"
cp -r "$root/tutorials/indentation/averageCell"/{system,constant} .
rm -f constant/cell.msh
gmsh -2 -setnumber D 16.8 -setnumber H 7.9 -setnumber h 1.6 \
    -setnumber hc 0.8 -setnumber nm 24 "$root/tests/lib/cellFallback.geo" \
    -o constant/cell.msh > log.gmsh 2>&1
/usr/bin/python3 "$root/tests/lib/setProtocol.py" constant/indenterProperties \
    "A load 0.3e-6 3e-6" "B hold 0 5"
cp -r . "$work/indentationClean"
# a user's file beside the outputs: never removed
mkdir -p postProcessing/indentation
echo "my notes" > postProcessing/indentation/notes.txt
failsThenRuns cellIndentationFoam cellIndentationFoam \
    postProcessing/indentation/solid.h5.tmp
check "cellIndentationFoam: the user's file beside the outputs is kept" \
    "[ \"\$(cat postProcessing/indentation/notes.txt)\" = 'my notes' ]"

# the first step failing on a fresh start (no postProcessing/ before: the
# folders it made go too)
cp -r "$work/indentationClean" "$work/indentationFirstStep"
cd "$work/indentationFirstStep"
cp constant/solidProperties "$work/solidProperties.good"
sed -i 's|cellMaterials/[A-Za-z0-9]*"|&\n    nucleus { C10 1e9; }|' constant/solidProperties
caseSums 'log.*' > "$work/firstStep.before"; paths > "$work/firstStep.paths.before"
status=0; cellIndentationFoam > log.fails 2>&1 || status=$?
check "cellIndentationFoam, first step failing: exits non-zero" \
    "[ $status -ne 0 ] && [ $status -lt 124 ] && grep -q 'did not converge' log.fails"
caseSums 'log.*' > "$work/firstStep.after"; paths > "$work/firstStep.paths.after"
check "cellIndentationFoam, first step failing: no output left (no postProcessing/)" \
    "cmp -s '$work/firstStep.before' '$work/firstStep.after' \
     && cmp -s '$work/firstStep.paths.before' '$work/firstStep.paths.after' && [ ! -e postProcessing ]"
cp "$work/solidProperties.good" constant/solidProperties
status=0; cellIndentationFoam > log.next 2>&1 || status=$?
check "cellIndentationFoam, first step failing: the next start runs" \
    "[ $status -eq 0 ] && grep -q '^End' log.next"

# a run that wrote rows before it failed (a force target its first row
# does not reach: refused at the row's end): its outputs are results of a
# run, kept, and the next start is refused over them as before
cp -r "$work/indentationClean" "$work/indentationLaterFailure"
cd "$work/indentationLaterFailure"
printf '\nforceTarget 1;\n' >> constant/indenterProperties
status=0; cellIndentationFoam > log.fails 2>&1 || status=$?
check "cellIndentationFoam failing after its first rows: exits non-zero, its rows kept" \
    "[ $status -ne 0 ] && [ $status -lt 124 ] && grep -q \"entry 'forceTarget' = 1 N was not reached\" log.fails \
     && [ \$(grep -vc '^#' postProcessing/indentation/force.dat) -gt 0 ]"
status=0; cellIndentationFoam > log.next 2>&1 || status=$?
check "cellIndentationFoam failing after its first rows: the next start is refused over them" \
    "[ $status -ne 0 ] && grep -q 'holds results of an earlier run' log.next"

# cellBlastFoam: the pulse through a layer, to 0.2 ns
mkdir "$work/fsi"; cd "$work/fsi"
cp -r "$root/tests/fsi/pulseLayer"/* .
blockMesh > log.blockMesh 2>&1
sed -i 's/^endTime .*/endTime 2e-10;/; s/^writeInterval .*/writeInterval 1e-10;/' system/controlDict
cp -r . "$work/fsiClean"
failsThenRuns cellBlastFoam cellBlastFoam solid/solid.h5.tmp

# The true full disk (root only: a small tmpfs)
fullDisk()
{
    local name=$1 solver=$2 clean=$3 fs=$work/fs.$1 status=0
    mkdir -p "$fs"
    if ! mount -t tmpfs -o size=${4:-4m} tmpfs "$fs" 2> /dev/null
    then
        echo "skip $name on a full disk (a tmpfs cannot be mounted: not root)"
        return 0
    fi
    cp -r "$clean" "$fs/case"
    cd "$fs/case"
    local free
    free=$(( $(stat -f -c '%a*%S' .) - 8192 ))
    head -c $free /dev/zero > ../filler 2> /dev/null || true
    caseSums 'log.*' > "$work/$name.full.before"; paths > "$work/$name.full.paths.before"
    $solver > "$work/$name.full.log" 2>&1 || status=$?
    check "$name on a full disk: exits non-zero, the message names the full file system" \
        "[ $status -ne 0 ] && [ $status -lt 124 ] \
         && grep -q 'bytes free.*No space left on device' '$work/$name.full.log'"
    caseSums 'log.*' > "$work/$name.full.after"; paths > "$work/$name.full.paths.after"
    check "$name on a full disk: nothing it made is left" \
        "cmp -s '$work/$name.full.before' '$work/$name.full.after' \
         && cmp -s '$work/$name.full.paths.before' '$work/$name.full.paths.after'"
    rm -f ../filler
    status=0; $solver > log.next 2>&1 || status=$?
    check "$name on a full disk: space freed, the next start runs" \
        "[ $status -eq 0 ] && grep -q '^End' log.next"
    cd "$work"
    umount "$fs"
}
fullDisk cellIndentationFoam cellIndentationFoam "$work/indentationClean" 4m
fullDisk cellBlastFoam cellBlastFoam "$work/fsiClean" 8m

exit $fail
