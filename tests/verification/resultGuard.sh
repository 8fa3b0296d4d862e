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
#  - startFrom latestTime is not stopped (a restart continues the run),
#    and a restart to a later end time writes that time (whatever the
#    write interval counted from the restart);
#  - startFrom latestTime with nothing to continue from (the times after
#    the start deleted; cellIndentationFoam: restart.h5 deleted) is a new
#    start: refused as above, naming what is missing;
#  - cellIndentationFoam -overwrite whose first step fails leaves a
#    solid.xmf listing only steps of solid.h5.
set -euo pipefail
. "$(dirname "$0")/../lib/restartTools.sh"
. "$(dirname "$0")/../lib/checks.sh"

refused()
{
    local name=$1 solver=$2
    caseSums 'log.again' > "$work/$name.before"
    local status=0
    $solver > log.again 2>&1 || status=$?
    check "$name: a new start over the results exits non-zero" "[ $status -ne 0 ]"
    check "$name: the message names the results and the ways out" \
        "grep -q 'holds results of an earlier run' log.again \
         && grep -q 'Nothing was changed' log.again \
         && grep -q 'startFrom latestTime' log.again \
         && grep -q -- '-overwrite' log.again"
    caseSums 'log.again' > "$work/$name.after"
    check "$name: no file of the case changed" \
        "cmp -s '$work/$name.before' '$work/$name.after'"
}

# timeDirectorySolver SOLVER: in a meshed case with a controlDict, run to
# 20 ns, then the refusal, -overwrite to 10 ns, and a restart to 15 ns
timeDirectorySolver()
{
    local solver=$1 status=0
    sed -i 's/^startFrom .*/startFrom startTime;/; s/^endTime .*/endTime 2e-8;/; s/^writeInterval .*/writeInterval 5e-9;/' system/controlDict
    $solver > log.first 2>&1
    refused $solver $solver
    sed -i 's/^endTime .*/endTime 1e-8;/' system/controlDict
    $solver -overwrite > log.overwrite 2>&1 || status=$?
    check "$solver: -overwrite runs, no later time of the first run left" \
        "[ $status -eq 0 ] && [ \"\$(foamListTimes -latestTime 2>/dev/null | tail -1)\" = 1e-08 ]"
    sed -i 's/^startFrom .*/startFrom latestTime;/; s/^endTime .*/endTime 1.5e-8;/' system/controlDict
    status=0; $solver > log.continue 2>&1 || status=$?
    check "$solver: startFrom latestTime continues" "[ $status -eq 0 ]"
    # A restart with a longer end time and a write interval that, counted
    # from the restart, misses it: the last time is written all the same
    # (issue 19: was no time written at all). The time steps are not
    # shortened to end on 1.7e-8 s (OpenFOAM aligns them with write
    # times only): the last time lies within half a step before it
    sed -i 's/^endTime .*/endTime 1.7e-8;/; s/^writeInterval .*/writeInterval 1e-7;/' system/controlDict
    status=0; $solver > log.extend 2>&1 || status=$?
    local last
    last=$(foamListTimes -latestTime 2>/dev/null | tail -1)
    check "$solver: a restart to a later end time writes its last time ($last s)" \
        "[ $status -eq 0 ] && awk -v t='$last' 'BEGIN{exit !(t > 1.69e-8 && t <= 1.7e-8)}' \
         && [ -f '$last/.writeCommitted' ] && [ -f '$last/p' ]"
    # startFrom latestTime with every time after the start deleted: the
    # latest time is the start, nothing to continue; a run would start
    # anew over the results (issue 19: replaced them, the blast's
    # solid/solid.h5 with it); refused, then -overwrite runs
    local again=$work/$solver.timesDeleted
    cp -r . "$again"
    pushd "$again" > /dev/null
        rm -rf $(foamListTimes)    # every time but 0
        refused "$solver.timesDeleted" $solver
        check "$solver (times deleted): the message says nothing is left to continue" \
            "grep -q 'startFrom latestTime, but there is nothing to continue from (no time directory after the start time 0 s)' log.again"
        status=0; $solver -overwrite > log.overwrite 2>&1 || status=$?
        check "$solver (times deleted): -overwrite starts anew" \
            "[ $status -eq 0 ] && [ \"\$(foamListTimes | wc -l)\" -ge 1 ]"
    popd > /dev/null
    # -overwrite from the first time over a run restarted twice: the
    # function objects' segments of the restarts (postProcessing/<name>/
    # 1e-08, 1.5e-08) go too, or the new run's rows are joined by time
    # with the earlier run's (adv38 x18)
    local segments
    segments=$(ls -d postProcessing/*/1e-08 postProcessing/*/1.5e-08 2>/dev/null | wc -l)
    sed -i 's/^startFrom .*/startFrom startTime;/; s/^endTime .*/endTime 5e-9;/; s/^writeInterval .*/writeInterval 5e-9;/' system/controlDict
    status=0; $solver -overwrite > log.overwrite2 2>&1 || status=$?
    check "$solver: -overwrite over a restarted run leaves no later segment of its function objects ($segments before)" \
        "[ $status -eq 0 ] && [ $segments -ge 2 ] \
         && [ -z \"\$(ls -A postProcessing/*/ | grep -v -x -e 0 -e 'postProcessing/.*:' -e '')\" ]"
}

mkdir "$work/fluid"; cd "$work/fluid"
cp -r "$root/tutorials/verification/waterPulseWall"/{0.orig,system,constant} .
rm -rf constant/polyMesh; cp -r 0.orig 0
blockMesh > log.blockMesh 2>&1
timeDirectorySolver rhoRiemannFoam

mkdir "$work/fsi"; cd "$work/fsi"
cp -r "$root/tests/fsi/pulseLayer"/* .
blockMesh > log.blockMesh 2>&1
timeDirectorySolver cellBlastFoam

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
# startFrom latestTime without restart.h5: nothing to continue from, the
# run would start anew over force.dat, peaks.dat, solid.h5 (issue 19: it
# did); refused naming the missing checkpoint
cp -r . "$work/indentationNoCheckpoint"
pushd "$work/indentationNoCheckpoint" > /dev/null
    sed -i 's/^startFrom .*/startFrom       latestTime;/' system/controlDict
    rm postProcessing/indentation/restart.h5
    refused cellIndentationFoam.noCheckpoint cellIndentationFoam
    check "cellIndentationFoam (no restart.h5): the missing checkpoint is named" \
        "grep -q 'nothing to continue from (no checkpoint .*postProcessing/indentation/restart.h5)' log.again"
popd > /dev/null
# -overwrite whose first step fails: solid.h5 is new (no step), and
# solid.xmf must list none of the earlier run's steps (issue 19: it listed
# them all)
cp -r . "$work/indentationOverwriteFails"
pushd "$work/indentationOverwriteFails" > /dev/null
    sed -i 's|cellMaterials/textFactor4"|&\n    nucleus { C10 1e9; }|' constant/solidProperties
    status=0; cellIndentationFoam -overwrite > log.fails 2>&1 || status=$?
    check "cellIndentationFoam -overwrite, first step failing: exits non-zero" "[ $status -ne 0 ]"
    check "cellIndentationFoam -overwrite, first step failing: solid.xmf lists only steps of solid.h5" \
        "/usr/bin/python3 - <<'PY'
import re
from neuronFsi.solidResults import SolidResults
with SolidResults('postProcessing/indentation/solid.h5') as r:
    steps = set(str(k) for k in r.steps())
listed = set(re.findall(r'solid.h5:/steps/(\d+)/',
                        open('postProcessing/indentation/solid.xmf').read()))
assert listed <= steps, sorted(listed - steps)
PY"
popd > /dev/null

# In parallel, the times reconstructed into the whole case (reconstructPar)
# are results too. A new start on processor directories decomposed anew
# (decomposePar -force -time 0: the start time only; the probes' output
# moved away) used to run without a word, and the next reconstructPar
# replaced the reconstructed times or mixed two runs (-overwrite left
# them); now refused, and -overwrite removes them as well
mkdir "$work/parallel"; cd "$work/parallel"
cp -r "$root/tutorials/verification/waterPulseWall"/{0.orig,system,constant} .
rm -rf constant/polyMesh; cp -r 0.orig 0
printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmethod simple;\ncoeffs { n (2 1 1); }\n' > system/decomposeParDict
sed -i 's/^startFrom .*/startFrom startTime;/; s/^endTime .*/endTime 2e-8;/; s/^writeInterval .*/writeInterval 5e-9;/' system/controlDict
blockMesh > log.blockMesh 2>&1
decomposePar > log.decomposePar 2>&1
mpirun -np 2 rhoRiemannFoam -parallel > log.first 2>&1
reconstructPar > log.reconstructPar 2>&1
decomposePar -force -time 0 > log.decomposeAgain 2>&1
# the probes' output moved away: the reconstructed times are the results
rm -rf postProcessing
# (.runLock aside: a parallel FatalError ends in MPI_Abort, which leaves
# the lock, taken over as stale by the next run: src/foamTools/caseLock.H)
caseSums 'log.*' | grep -v '/\.runLock$' > "$work/parallel.before"
status=0
mpirun -np 2 rhoRiemannFoam -parallel > log.again 2>&1 || status=$?
check "rhoRiemannFoam -parallel: a new start over reconstructed times exits non-zero" \
    "[ $status -ne 0 ]"
check "rhoRiemannFoam -parallel: the message names the reconstructed times" \
    "grep -q '4 time directories of the case directory after the start time (5e-09 ... 2e-08 s in .*: reconstructed by reconstructPar; a later reconstructPar of this run would write over them)' log.again \
     && grep -q 'Nothing was changed' log.again"
caseSums 'log.*' | grep -v '/\.runLock$' > "$work/parallel.after"
check "rhoRiemannFoam -parallel: no file of the case changed" \
    "cmp -s '$work/parallel.before' '$work/parallel.after'"
sed -i 's/^endTime .*/endTime 1e-8;/' system/controlDict
status=0
mpirun -np 2 rhoRiemannFoam -parallel -overwrite > log.overwrite 2>&1 || status=$?
check "rhoRiemannFoam -parallel -overwrite: runs, no reconstructed time of the first run left" \
    "[ $status -eq 0 ] && [ -d processor1/1e-08 ] && [ ! -e 5e-09 ] && [ ! -e 2e-08 ]"
# A serial new start over the parallel run's processor times: refused, and
# -overwrite moves them aside too (adv38 x16: they were left, and a later
# reconstructPar wrote the earlier run's fields over the serial run's)
status=0
rhoRiemannFoam > log.serial 2>&1 || status=$?
check "rhoRiemannFoam serial over processor*/ times: refused, naming them" \
    "[ $status -ne 0 ] && grep -q 'of an earlier parallel run in the processor folders' log.serial \
     && [ -d processor1/1e-08 ] && [ ! -e 1e-08 ]"
status=0
rhoRiemannFoam -overwrite > log.serialOverwrite 2>&1 || status=$?
check "rhoRiemannFoam serial -overwrite: runs, no processor time after the start left" \
    "[ $status -eq 0 ] && [ -d 1e-08 ] && [ ! -e processor0/5e-09 ] && [ ! -e processor1/1e-08 ]"
# ... and a parallel new start over that serial run's own times: refused,
# naming them as a serial run's (adv39 y06, y07: they were called "time
# directories reconstructed into the case")
status=0
mpirun -np 2 rhoRiemannFoam -parallel > log.parallelOverSerial 2>&1 || status=$?
check "rhoRiemannFoam -parallel over a serial run's times: refused, naming them as the serial run's" \
    "[ $status -ne 0 ] && grep -q 'time directories of the case directory after the start time (5e-09 ... 1e-08 s in .*: written by a serial run of the case;' log.parallelOverSerial \
     && ! grep -q 'reconstructed by reconstructPar' log.parallelOverSerial"

# A 2-rank -overwrite killed before its first write leaves each rank's
# later times and the master's function-object folders moved aside; the
# next run with nothing to continue from is refused, and the message is
# the master's, printed once, naming every rank's times moved aside and
# the master's folders (adv37 w86: only rank 1's part was printed, "moved
# them aside as well:" followed by nothing, and the job stopped before the
# master's message came out)
mkdir "$work/parallelKilled"; cd "$work/parallelKilled"
cp -r "$root/tutorials/verification/waterPulseWall"/{0.orig,system,constant} .
rm -rf constant/polyMesh; cp -r 0.orig 0
printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmethod simple;\ncoeffs { n (2 1 1); }\n' > system/decomposeParDict
sed -i 's/^startFrom .*/startFrom startTime;/; s/^endTime .*/endTime 1e-8;/; s/^writeInterval .*/writeInterval 5e-9;/' system/controlDict
blockMesh > log.blockMesh 2>&1
decomposePar > log.decomposePar 2>&1
mpirun -np 2 rhoRiemannFoam -parallel > log.first 2>&1
# as -overwrite leaves them when killed before its first write
for p in processor0 processor1
do
    for t in 5e-09 1e-08; do mv $p/$t $p/.$t.overwritten; done
done
mv postProcessing/probes/0 postProcessing/probes/.0.overwritten
sed -i 's/^startFrom .*/startFrom latestTime;/' system/controlDict
status=0
mpirun -np 2 rhoRiemannFoam -parallel > log.again 2>&1 || status=$?
check "rhoRiemannFoam -parallel after a killed -overwrite: refused, one message naming both ranks' times and the master's folder" \
    "[ $status -ne 0 ] && [ \$(grep -c 'FOAM FATAL' log.again) -eq 1 ] \
     && [ \$(grep -c 'holds results of an earlier run' log.again) -eq 1 ] \
     && grep -q '^ *[^ ]*/processor0: .1e-08.overwritten .5e-09.overwritten\$' log.again \
     && grep -q '^ *[^ ]*/processor1: .1e-08.overwritten .5e-09.overwritten\$' log.again \
     && grep -q 'postProcessing/probes/.0.overwritten' log.again \
     && ! grep -q '^\\[1\\]' log.again"


# A serial -overwrite killed before its first write leaves the earlier
# times and the function objects' folder moved aside (.<name>.overwritten)
# and its own partial outputs; a plain new start (startFrom startTime) is
# refused, and the message names both the partial outputs and the
# results kept aside, and how to get them back and continue (adv45 b36:
# it named only the partial files and advised -overwrite). Without
# partial outputs the new start runs and says that the names moved aside
# are kept, untouched
mkdir "$work/serialKilled"; cd "$work/serialKilled"
cp -r "$root/tutorials/verification/waterPulseWall"/{0.orig,system,constant} .
rm -rf constant/polyMesh; cp -r 0.orig 0
sed -i 's/^startFrom .*/startFrom startTime;/; s/^endTime .*/endTime 1e-8;/; s/^writeInterval .*/writeInterval 5e-9;/' system/controlDict
blockMesh > log.blockMesh 2>&1
rhoRiemannFoam > log.first 2>&1
# as -overwrite leaves them when killed before its first write: the
# earlier run's aside, the killed run's probe file begun anew
for t in 5e-09 1e-08; do mv $t .$t.overwritten; done
mv postProcessing/probes/0 postProcessing/probes/.0.overwritten
mkdir postProcessing/probes/0
printf '# Probe 0 (0.0001 0 0)\n' > postProcessing/probes/0/p
caseSums 'log.*' > "$work/serialKilled.before"
status=0
rhoRiemannFoam > log.again 2>&1 || status=$?
check "rhoRiemannFoam startFrom startTime after a killed -overwrite: refused, naming the partial outputs and the results kept aside, and how to continue them" \
    "[ $status -ne 0 ] && grep -q 'holds results of an earlier run' log.again \
     && grep -q 'postProcessing/probes/0\$' log.again \
     && grep -q '^ *[^ ]*/serialKilled: .1e-08.overwritten .5e-09.overwritten\$' log.again \
     && grep -q 'postProcessing/probes/.0.overwritten' log.again \
     && grep -q 'set startFrom latestTime in system/controlDict and run again to continue them' log.again"
caseSums 'log.*' > "$work/serialKilled.after"
check "rhoRiemannFoam startFrom startTime after a killed -overwrite: no file of the case changed" \
    "cmp -s '$work/serialKilled.before' '$work/serialKilled.after'"
rm -rf postProcessing/probes/0
status=0
rhoRiemannFoam > log.new 2>&1 || status=$?
check "rhoRiemannFoam new start beside results moved aside: runs, says they are kept, leaves them" \
    "[ $status -eq 0 ] && grep -q 'Note: earlier results moved aside by an -overwrite run stopped before its first write are kept as they are' log.new \
     && [ -d .5e-09.overwritten ] && [ -d .1e-08.overwritten ] && [ -d postProcessing/probes/.0.overwritten ] && [ -d 1e-08 ]"

exit $fail
