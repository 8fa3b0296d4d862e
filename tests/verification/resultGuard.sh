#!/bin/bash
# A new start never replaces results without being asked (issue 19,
# class 2; src/foamTools/resultGuard.H), for the three solvers:
# rhoRiemannFoam (tutorials/verification/waterPulseWall, to 20 ns),
# cellBlastFoam (tests/fsi/pulseLayer, to 20 ns) and cellIndentationFoam
# (tutorials/indentation/validationCell, a two-row table). Each case is run
# once; then, from the start time again:
#  - without -overwrite the run exits non-zero, names the results it would
#    replace and how to keep, continue or replace them, and changes no
#    file of the case (every file's checksum equal, its own log aside);
#  - with -overwrite and a shorter end time it runs, and no time directory
#    of the first run after its own end is left (no mix of two runs);
#  - startFrom latestTime is not stopped (a restart continues the run).
set -euo pipefail
. "$(dirname "$0")/../lib/restartTools.sh"
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }
sums() { find . -type f ! -name 'log.again' -print0 | sort -z | xargs -0 md5sum; }

refused()
{
    local name=$1 solver=$2
    sums > "$work/$name.before"
    local status=0
    $solver > log.again 2>&1 || status=$?
    check "$name: a new start over the results exits non-zero" "[ $status -ne 0 ]"
    check "$name: the message names the results and the ways out" \
        "grep -q 'holds results of an earlier run' log.again \
         && grep -q 'Nothing was changed' log.again \
         && grep -q 'startFrom latestTime' log.again \
         && grep -q -- '-overwrite' log.again"
    sums > "$work/$name.after"
    check "$name: no file of the case changed" \
        "cmp -s '$work/$name.before' '$work/$name.after'"
}

# rhoRiemannFoam
mkdir "$work/fluid"; cd "$work/fluid"
cp -r "$root/tutorials/verification/waterPulseWall"/{0.orig,system,constant} .
rm -rf constant/polyMesh; cp -r 0.orig 0
sed -i 's/^startFrom .*/startFrom startTime;/; s/^endTime .*/endTime 2e-8;/; s/^writeInterval .*/writeInterval 5e-9;/' system/controlDict
blockMesh > log.blockMesh 2>&1
rhoRiemannFoam > log.first 2>&1
refused rhoRiemannFoam rhoRiemannFoam
sed -i 's/^endTime .*/endTime 1e-8;/' system/controlDict
status=0; rhoRiemannFoam -overwrite > log.overwrite 2>&1 || status=$?
check "rhoRiemannFoam: -overwrite runs, no later time of the first run left" \
    "[ $status -eq 0 ] && [ \"\$(foamListTimes -latestTime 2>/dev/null | tail -1)\" = 1e-08 ]"
sed -i 's/^startFrom .*/startFrom latestTime;/; s/^endTime .*/endTime 1.5e-8;/' system/controlDict
status=0; rhoRiemannFoam > log.continue 2>&1 || status=$?
check "rhoRiemannFoam: startFrom latestTime continues" "[ $status -eq 0 ]"

# cellBlastFoam
mkdir "$work/fsi"; cd "$work/fsi"
cp -r "$root/tests/fsi/pulseLayer"/* .
sed -i 's/^startFrom .*/startFrom startTime;/; s/^endTime .*/endTime 2e-8;/; s/^writeInterval .*/writeInterval 5e-9;/' system/controlDict
blockMesh > log.blockMesh 2>&1
cellBlastFoam > log.first 2>&1
refused cellBlastFoam cellBlastFoam
sed -i 's/^endTime .*/endTime 1e-8;/' system/controlDict
status=0; cellBlastFoam -overwrite > log.overwrite 2>&1 || status=$?
check "cellBlastFoam: -overwrite runs, no later time of the first run left" \
    "[ $status -eq 0 ] && [ \"\$(foamListTimes -latestTime 2>/dev/null | tail -1)\" = 1e-08 ]"
sed -i 's/^startFrom .*/startFrom latestTime;/; s/^endTime .*/endTime 1.5e-8;/' system/controlDict
status=0; cellBlastFoam > log.continue 2>&1 || status=$?
check "cellBlastFoam: startFrom latestTime continues" "[ $status -eq 0 ]"

# cellIndentationFoam
mkdir "$work/indentation"; cd "$work/indentation"
cp -r "$root/tutorials/indentation/validationCell"/{constant,system} .
rm -f constant/*.msh
/usr/bin/python3 "$root/tests/lib/setProtocol.py" constant/indenterProperties \
    "A load 0.3e-6 3e-6" "B hold 0 5"
cellMesh > log.cellMesh 2>&1
cellIndentationFoam > log.first 2>&1
refused cellIndentationFoam cellIndentationFoam
status=0; cellIndentationFoam -overwrite > log.overwrite 2>&1 || status=$?
check "cellIndentationFoam: -overwrite runs" \
    "[ $status -eq 0 ] && grep -q '^End' log.overwrite \
     && [ \$(grep -vc '^#' postProcessing/indentation/force.dat) -gt 0 ]"

exit $fail
