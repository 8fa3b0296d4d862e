#!/bin/bash
# A restart of cellIndentationFoam continues only with the inputs its
# checkpoint was computed with (issue 19, class 1; Foam::indentationInput::
# checkRestart, the record of src/foamTools/inputRecord.H in restart.h5).
# The average cell on a coarse mesh, a short table (A load, B hold, C1
# load and unload, E hold), a checkpoint every step, is killed (SIGKILL)
# once C1 has begun; then, each in a copy of the killed case, restarted
# with startFrom latestTime after changing
#  - a material value in its 7th significant digit (membrane C10),
#  - the mesh (cell.msh meshed finer),
#  - a protocol row that has run (row 1, A's amount),
#  - a contact setting (penaltyFactor),
#  - a stepping setting (maxDepthIncrement):
#    each restart exits non-zero, names the file and entry (row) and
#    changes no file of the case (md5 of every file);
#  - a material value of an included file (named with the file) and
#    another constraint of 'fixed' (fix19d, adv46b d02 (b));
#  - a row that has not run (row 5, E's hold time), a comment and the rows
#    of 'fixed' reordered (fix19d, adv46b d10 (a)): the restart continues
#    and runs to the new end of the table.
set -euo pipefail
. "$(dirname "$0")/../lib/restartTools.sh"
. "$(dirname "$0")/../lib/checks.sh"

out=postProcessing/indentation
# mesh H: the average cell's fallback mesh of element size H um
mesh()
{
    gmsh -2 -setnumber D 16.8 -setnumber H 7.9 -setnumber h "$1" \
        -setnumber hc 0.8 -setnumber nm 24 \
        "$root/tests/lib/cellFallback.geo" \
        -o constant/cell.msh > log.gmsh 2>&1
}

case=$work/killed
mkdir "$case"; cd "$case"
cp -r "$root/tutorials/indentation/averageCell"/{system,constant} .
rm -f constant/cell.msh
mesh 1.6
/usr/bin/python3 "$root/tests/lib/setProtocol.py" constant/indenterProperties \
    "A load 0.3e-6 0.3e-6" "B hold 0 1" "C1 load 10e-6 1e-6" \
    "C1 unload 10e-6 1e-6" "E hold 0 5"
sed -i 's/^startFrom .*/startFrom       latestTime;/' system/controlDict
printf '\ncheckpointInterval 1;\n' >> system/controlDict
runUntil KILL "grep -qs ' C1\$' $out/force.dat" log.first cellIndentationFoam
# The killed run's lock (caseLock), which every restart would replace
rm -f .runLock
# The checkpoint's row (from 1): rows after it have not run
row=$(/usr/bin/python3 -c "import h5py; print(int(h5py.File('$out/restart.h5')['row'][0]) + 1)")
echo "killed in stage C1; checkpoint in row $row"
# (the record read whole: h5dump wraps a long text attribute across lines,
# and the record with the materials by entry, fix19d, is cut inside
# "row 1" where the test looked for it)
check "the checkpoint records its inputs and lies before row 5" \
    "[ $row -lt 5 ] && /usr/bin/python3 -c \"import h5py, sys; t = h5py.File('$out/restart.h5', 'r').attrs['inputDigests']; t = t.decode() if isinstance(t, bytes) else str(t); sys.exit(\\\"entry 'protocol', row 1\\\" not in t)\""

# refusedAfter NAME FILE EXPECTED COMMAND: run COMMAND in a copy of the
# killed case, restart, expect the refusal with the line EXPECTED (the
# file and entry) and no file changed
refusedAfter()
{
    local name=$1 expected=$2
    shift 2
    rm -rf "$work/edit"; cp -r "$case" "$work/edit"; cd "$work/edit"
    eval "$@"
    caseSums > "$work/before"
    local status=0
    cellIndentationFoam > log.restart 2>&1 || status=$?
    caseSums > "$work/after"
    local line="    $expected"
    case $expected in *"(changed"*) ;; *) line="$line (changed)" ;; esac
    check "$name: the restart is refused, naming $expected, nothing changed" \
        "[ $status -ne 0 ] && grep -q 'its state was computed with other inputs' log.restart \
         && grep -qF \"$line\" log.restart && cmp -s '$work/before' '$work/after'"
    [ $status -ne 0 ] || tail -3 log.restart
    cd "$case"
}

refusedAfter "a material value (7th digit)" \
    "constant/solidProperties, entry 'materials/membrane/C10'" \
    "sed -i 's#cellMaterials/textFactor4\"#&\n    membrane { C10 166.67001; }#' constant/solidProperties"
# a value of an included file: named by its entry and the file (fix19d,
# adv46b d02 (b): "region 'nucleus' (changed)", neither mu1 nor the file)
refusedAfter "a material value of an included file" \
    "constant/solidProperties, entry 'materials/nucleus/mu1' (changed; read from constant/mats)" \
    "cp \"\$root/etc/caseDicts/cellMaterials/textFactor4\" constant/mats && sed -i 's/mu1         431.12;/mu1         500;/' constant/mats && sed -i 's#\\\$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4#mats#' constant/solidProperties"
# another constraint: named as the set of rows of 'fixed'
refusedAfter "another constraint" \
    "constant/solidProperties, entry 'fixed' (its rows as a set)" \
    "sed -i 's/(axis 0) *\\/\\/ u_r/(axis 0) (axis 1) \\/\\/ u_r/' constant/solidProperties"
refusedAfter "the mesh" "constant/cell.msh" "mesh 1.5"
refusedAfter "a row already run" \
    "constant/indenterProperties, entry 'protocol', row 1" \
    "sed -i 's/(A *load *0.3e-6 *0.3e-6)/(A load 0.3e-6 0.31e-6)/' constant/indenterProperties"
refusedAfter "a contact setting" \
    "constant/indenterProperties, entry 'penaltyFactor'" \
    "sed -i 's/^penaltyFactor .*/penaltyFactor 20;/' constant/indenterProperties"
refusedAfter "a stepping setting" \
    "constant/indenterProperties, entry 'maxDepthIncrement'" \
    "sed -i 's/^maxDepthIncrement .*/maxDepthIncrement 0.05e-6;/' constant/indenterProperties"

# A row not yet run, a comment and the rows of 'fixed' in another order
# (fix19d, adv46b d10 (a): the same constraints were "(changed)") are no
# change: the run continues
sed -i 's/(E *hold *0 *5)/(E hold 0 8)/' constant/indenterProperties
sed -i 's/(fixedBottom 0) (fixedBottom 1)/(fixedBottom 1) (fixedBottom 0)/' constant/solidProperties
grep -q '(fixedBottom 1) (fixedBottom 0)' constant/solidProperties
sed -i 's#^materials#// a comment added before the restart\nmaterials#' constant/solidProperties
status=0
cellIndentationFoam > log.restart 2>&1 || status=$?
check "a row not yet run (row 5) and a comment: the restart continues to the new end (8 s of E)" \
    "[ $status -eq 0 ] && grep -q 'Continuing from' log.restart && grep -q '^End' log.restart \
     && [ \"\$(grep -v '^#' $out/force.dat | tail -1 | awk '{print \$6}')\" = E ] \
     && /usr/bin/python3 -c \"import sys; t = float(open('$out/force.dat').read().split('\\n')[-2].split()[0]); sys.exit(abs(t - (1 + 1 + 0.1 + 0.1 + 8)) > 1e-9)\""
[ $status -eq 0 ] || tail -5 log.restart
exit $fail
