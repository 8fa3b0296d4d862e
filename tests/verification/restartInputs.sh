#!/bin/bash
# A restart continues only with the inputs its results were computed with
# (issue 19, class 1; src/foamTools/inputRecord.H). The pulse-layer FSI
# case (cellBlastFoam) and the pulse-wall case (rhoRiemannFoam) are run to
# 10 ns (writes every 5 ns); then, with startFrom latestTime and a later
# end time:
#  - a changed material (solid rho0, the water's C0), a changed coupling
#    setting, a changed scheme, a changed mesh point, an added file in
#    constant/: each restart exits non-zero, names the file and changes
#    nothing in the case;
#  - the pulse table edited in the restart time's p (a boundary
#    condition: recorded per field and patch) is refused;
#  - solid/solid.h5 of another run (another solid rho0), and solid.h5
#    with a bit of step 0 flipped (the restart reads step 1): refused,
#    naming the file (and the dataset), nothing changed;
#  - the water's coefficients moved into constant/water/eos, which
#    thermophysicalProperties #includes, are not a change (adv42 g07
#    (a0)); C0 changed there is refused naming the entry and that file;
#  - an edited comment and layout, and a changed end time, are not
#    changes: the restart runs (the boundary conditions read from the
#    written time equal those recorded from 0/);
#  - every write time records the digests (uniform/inputDigests);
#  - 0/p's table rewritten with its size and 17 digits (as decomposePar
#    writes it) is the same condition: the restart runs, and each rank's
#    record of a 2-rank run holds the serial run's digest of it;
#  - on 2 ranks each rank records its own mesh, a changed point of one
#    rank is refused, and the reconstructed run restarts serially;
#  - the pulse read by tableFile from constant/tables/pulse.dat or from
#    tables/pulse.dat (outside constant/), edited: refused naming the file
#    (adv42 g05); unchanged: the restart runs.
#  - rhoRiemannFoam, mieGruneisenCoeffs' entries reordered: refused, the
#    order named as what differs (fix19d, adv46b d14 (a)).
set -euo pipefail
. "$(dirname "$0")/../lib/restartTools.sh"
. "$(dirname "$0")/../lib/checks.sh"

# refusedAfter NAME SOLVER FILE EDIT: apply the sed EDIT to FILE in a copy
# of the case, restart, expect the refusal naming FILE and no change
refusedAfter()
{
    local name=$1 solver=$2 file=$3 edit=$4
    rm -rf "$work/edit"; cp -r "$case" "$work/edit"; cd "$work/edit"
    if [ -n "$edit" ]; then sed -i "$edit" "$file"; else echo "x" > "$file"; fi
    caseSums > "$work/before"
    local status=0
    $solver > log.restart 2>&1 || status=$?
    caseSums > "$work/after"
    check "$name: the restart is refused, naming $file, nothing changed" \
        "[ $status -ne 0 ] && grep -q 'would continue the results with other inputs' log.restart \
         && grep -q '    $file (' log.restart && cmp -s '$work/before' '$work/after'"
    cd "$case"
}

# cellBlastFoam
case=$work/fsi
mkdir "$case"; cd "$case"
cp -r "$root/tests/fsi/pulseLayer"/* .
sed -i 's/^startFrom .*/startFrom latestTime;/; s/^endTime .*/endTime 1e-8;/; s/^writeInterval .*/writeInterval 5e-9;/' system/controlDict
blockMesh > log.blockMesh 2>&1
cellBlastFoam > log.first 2>&1
check "cellBlastFoam: each write time records its inputs, only those" \
    "[ \"\$(foamListTimes -withZero | tr '\\n' ' ')\" = '0 5e-09 1e-08 ' ] \
     && [ -s 5e-09/uniform/inputDigests ] && [ -s 1e-08/uniform/inputDigests ] \
     && grep -q ' constant/solidProperties\$' 1e-08/uniform/inputDigests \
     && grep -q ' constant/polyMesh/points\$' 1e-08/uniform/inputDigests"
sed -i 's/^endTime .*/endTime 1.5e-8;/' system/controlDict
refusedAfter "cellBlastFoam, solid rho0" cellBlastFoam constant/solidProperties \
    's/rho0        1000;/rho0        1100;/'
refusedAfter "cellBlastFoam, coupling tolerance" cellBlastFoam constant/fsiProperties \
    's/tolerance       1e-6;/tolerance       1e-5;/'
refusedAfter "cellBlastFoam, water C0" cellBlastFoam constant/thermophysicalProperties \
    's/\(C0 *\)[0-9.e+-]*;/\11460;/'
refusedAfter "cellBlastFoam, a mesh point" cellBlastFoam constant/polyMesh/points \
    '0,/^(0 -/s/^(0 -/(1e-9 -/'
refusedAfter "cellBlastFoam, an added file" cellBlastFoam constant/notes ""
# The pulse table in the restart time's p (adversarial pass of 2026-12-03:
# the run went on at 90 MPa after 10 ns at 50 MPa, exit 0)
rm -rf "$work/edit"; cp -r "$case" "$work/edit"; cd "$work/edit"
sed -i 's/ 50000000)/ 90000000)/g' 1e-08/p
caseSums > "$work/before"
status=0; cellBlastFoam > log.restart 2>&1 || status=$?
caseSums > "$work/after"
check "cellBlastFoam, the pulse table in 1e-08/p: refused, naming the field and patch, nothing changed" \
    "[ $status -ne 0 ] && grep -q '    field p, boundaryField/loaded (changed)' log.restart \
     && cmp -s '$work/before' '$work/after'"
# solid/solid.h5 of another run (adversarial pass: continued silently,
# one file of two runs) and damaged in step 0, before the step restarted
# from (continued silently, the damage kept): refused naming the file
cp -r "$case" "$work/other"; cd "$work/other"
sed -i 's/rho0        1000;/rho0        1100;/' constant/solidProperties
foamListTimes -rm > /dev/null; rm -rf solid postProcessing
cellBlastFoam > log.other 2>&1
rm -rf "$work/edit"; cp -r "$case" "$work/edit"; cd "$work/edit"
cp "$work/other/solid/solid.h5" solid/solid.h5
caseSums > "$work/before"
status=0; cellBlastFoam > log.restart 2>&1 || status=$?
caseSums > "$work/after"
check "cellBlastFoam, solid.h5 of another run: refused, naming it, nothing changed" \
    "[ $status -ne 0 ] && grep -q 'solid/solid.h5.* belongs to another run' log.restart \
     && cmp -s '$work/before' '$work/after'"
rm -rf "$work/edit"; cp -r "$case" "$work/edit"; cd "$work/edit"
# one bit of the largest value (Fletcher-32 cannot tell 16-bit words 0x0000
# from 0xffff: zeroed or inverted zeros, most of step 0, go unseen)
/usr/bin/python3 - <<'PY'
import h5py, numpy as np
with h5py.File("solid/solid.h5", "r") as f:
    d = f["steps/0/displacement"]
    at = d.id.get_chunk_info(0).byte_offset + 8*int(np.argmax(abs(d[:])))
with open("solid/solid.h5", "r+b") as f:
    f.seek(at + 3)
    b = f.read(1)[0]
    f.seek(at + 3)
    f.write(bytes([b ^ 0x10]))
PY
caseSums > "$work/before"
status=0; cellBlastFoam > log.restart 2>&1 || status=$?
caseSums > "$work/after"
check "cellBlastFoam, solid.h5 damaged in step 0: refused, naming file and dataset, nothing changed" \
    "[ $status -ne 0 ] && grep -q \"solid/solid.h5'.*/steps/0/displacement.*checksum\" log.restart \
     && cmp -s '$work/before' '$work/after'"
# 0/p's pulse table written as decomposePar and the solver write it (its
# size before the list, 17 digits), the same rows: not a change (adv38 x75:
# refused as a changed initial condition, the digest was of the text)
rm -rf "$work/edit"; cp -r "$case" "$work/edit"; cd "$work/edit"
/usr/bin/python3 - <<'PY'
import re
s = open("0/p").read()
m = re.search(r"(uniformValue\s+table\s*)\((.*?)\n\s*\);", s, re.S)
rows = re.findall(r"\(\s*([^()\s]+)\s+([^()\s]+)\s*\)", m.group(2))
text = "%d(%s)" % (len(rows), " ".join("(%.17g %.17g)" % (float(a), float(b))
                                        for a, b in rows))
open("0/p", "w").write(s[:m.start()] + m.group(1) + text + ";" + s[m.end():])
PY
status=0; cellBlastFoam > log.restart 2>&1 || status=$?
check "cellBlastFoam: 0/p's table rewritten with its size and 17 digits (the same rows) is not a change" \
    "tr -s ' \n' ' ' < 0/p | grep -q 'uniformValue table 5((0 0) (1e-10 50000000) (5.0000000000000001e-09 50000000)' \
     && [ $status -eq 0 ] && grep -q '^End' log.restart && [ -d 1.5e-08 ]"
# The water's coefficients moved into a file under constant/ that
# thermophysicalProperties #includes (adv42 g07 (a0): the same numbers were
# refused as "constant/water/eos (added)"): what the run reads is the same,
# the restart runs; C0 changed there: refused naming the dictionary, the
# entry and the file it is read from, nothing changed
moveEos()
{
    mkdir -p constant/water
    /usr/bin/python3 - <<'PY'
import re
p = "constant/thermophysicalProperties"; t = open(p).read()
m = re.search(r"mieGruneisenCoeffs\s*\{[^{}]*\}", t)
open("constant/water/eos", "w").write(m.group(0) + "\n")
open(p, "w").write(t[:m.start()] + '#include "water/eos"' + t[m.end():])
PY
}
rm -rf "$work/edit"; cp -r "$case" "$work/edit"; cd "$work/edit"
moveEos
sed -i 's/\(C0 *\)[0-9.e+-]*;/\11460;/' constant/water/eos
caseSums > "$work/before"
status=0; cellBlastFoam > log.restart 2>&1 || status=$?
caseSums > "$work/after"
check "cellBlastFoam, C0 changed in constant/water/eos (included): refused, naming the entry and the file, nothing changed" \
    "[ $status -ne 0 ] && grep -q 'would continue the results with other inputs' log.restart \
     && grep -qF \"    constant/thermophysicalProperties, entry 'mieGruneisenCoeffs/C0' (changed; read from constant/water/eos)\" log.restart \
     && ! grep -q 'constant/water/eos (added)' log.restart && cmp -s '$work/before' '$work/after'"
rm -rf "$work/edit"; cp -r "$case" "$work/edit"; cd "$work/edit"
moveEos
status=0; cellBlastFoam > log.restart 2>&1 || status=$?
check "cellBlastFoam: the same coefficients moved into constant/water/eos (included) are not a change" \
    "[ $status -eq 0 ] && grep -q '^End' log.restart && [ -d 1.5e-08 ]"
# An optional include (the tutorials' #sinclude "fsiProperties.allrun")
# of a file absent at the run, then there but empty: what the run reads is
# the same, the restart runs (adv45 b38 (c): refused as
# "constant/fsiProperties.allrun (added)"); with a coupling entry in it:
# refused naming the entry and the file
rm -rf "$work/edit"; cp -r "$case" "$work/edit"; cd "$work/edit"
printf '\n#sinclude "fsiProperties.allrun"\n' >> constant/fsiProperties
printf 'coupling\n{\n    tolerance 1e-5;\n}\n' > constant/fsiProperties.allrun
caseSums > "$work/before"
status=0; cellBlastFoam > log.restart 2>&1 || status=$?
caseSums > "$work/after"
check "cellBlastFoam, coupling/tolerance set in an #sincluded constant/fsiProperties.allrun: refused, naming the entry and the file, nothing changed" \
    "[ $status -ne 0 ] && grep -qF \"    constant/fsiProperties, entry 'coupling/tolerance' (changed; read from constant/fsiProperties.allrun)\" log.restart \
     && ! grep -q 'fsiProperties.allrun (added)' log.restart && cmp -s '$work/before' '$work/after'"
: > constant/fsiProperties.allrun
status=0; cellBlastFoam > log.restart 2>&1 || status=$?
check "cellBlastFoam: an empty #sincluded constant/fsiProperties.allrun is not a change" \
    "[ $status -eq 0 ] && grep -q '^End' log.restart && [ -d 1.5e-08 ]"
cd "$case"
sed -i 's#^\(materials\)#// a comment added before the restart\n\1#; s/rho0        1000;/rho0  1000 ;/' constant/solidProperties
status=0; cellBlastFoam > log.restart 2>&1 || status=$?
check "cellBlastFoam: a comment, the layout and the end time are not changes" \
    "[ $status -eq 0 ] && grep -q '^End' log.restart && [ -d 1.5e-08 ]"

# cellBlastFoam on 2 ranks: a changed point of one rank's mesh is
# refused, naming that rank's file; the run reconstructed and restarted
# serially is not refused (the record of processor0's mesh does not apply
# to the whole mesh)
case=$work/fsiParallel
mkdir "$case"; cd "$case"
cp -r "$root/tests/fsi/pulseLayer"/* .
sed -i 's/^startFrom .*/startFrom latestTime;/; s/^endTime .*/endTime 1e-8;/; s/^writeInterval .*/writeInterval 5e-9;/' system/controlDict
printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmethod simple;\ncoeffs { n (2 1 1); }\n' > system/decomposeParDict
blockMesh > log.blockMesh 2>&1
decomposePar > log.decomposePar 2>&1
mpirun -np 2 cellBlastFoam -parallel > log.first 2>&1
check "cellBlastFoam -parallel: the ranks record their own meshes" \
    "grep -q ' processor1/constant/polyMesh/points\$' processor1/1e-08/uniform/inputDigests"
# The initial conditions as their patch fields write them: decomposePar's
# processorN/0/p (the table with its size and 17 digits) records the
# digest of the serial run's 0/p (adv38 x73: planeWave refused every
# unchanged 2-rank run, "0/p, boundaryField/top changed since the run")
initialDigest() { sed -n "s|^\([0-9a-f]*\)  initial boundary condition $2, boundaryField/loaded\$|\1|p" "$1"; }
serialDigest=$(initialDigest "$work/fsi/1e-08/uniform/inputDigests" 0/p)
check "cellBlastFoam -parallel: each rank's 0/p pulse condition has the serial run's digest" \
    "[ -n '$serialDigest' ] \
     && [ \"\$(initialDigest processor0/1e-08/uniform/inputDigests processor0/0/p)\" = '$serialDigest' ] \
     && [ \"\$(initialDigest processor1/1e-08/uniform/inputDigests processor1/0/p)\" = '$serialDigest' ]"
sed -i 's/^endTime .*/endTime 1.5e-8;/' system/controlDict
rm -rf "$work/edit"; cp -r "$case" "$work/edit"; cd "$work/edit"
/usr/bin/python3 - <<'PY'
import re
f='processor1/constant/polyMesh/points'; s=open(f).read()
m=re.search(r'\(([-0-9.e+]+) ', s[s.index('(\n'):])
open(f,'w').write(s.replace('('+m.group(1)+' ', '('+repr(float(m.group(1))+1e-9)+' ', 1))
PY
status=0; mpirun -np 2 cellBlastFoam -parallel > log.restart 2>&1 || status=$?
check "cellBlastFoam -parallel: a changed point of rank 1 is refused, naming its file" \
    "[ $status -ne 0 ] && grep -q '    processor1/constant/polyMesh/points (changed)' log.restart"
cd "$case"
reconstructPar -latestTime > log.reconstructPar 2>&1
status=0; cellBlastFoam > log.serial 2>&1 || status=$?
check "cellBlastFoam: the reconstructed run restarts serially" \
    "[ $status -eq 0 ] && grep -q '^End' log.serial && [ -d 1.5e-08 ]"

# The pulse read by OpenFOAM's tableFile from a file (adv42 g05: a table in
# constant/tables/, a sub-folder of constant/, edited after the run: the
# restart went on with the new pulse, exit 0). Every file in constant/ and
# its sub-folders is an input, and so is a file a boundary condition names
# wherever it lies (here tables/ of the case): each edit refused naming
# the file, nothing changed; the unchanged restart runs
for table in constant/tables/pulse.dat tables/pulse.dat
do
    case=$work/tableFile
    rm -rf "$case"; mkdir "$case"; cd "$case"
    cp -r "$root/tests/fsi/pulseLayer"/* .
    sed -i 's/^startFrom .*/startFrom latestTime;/; s/^endTime .*/endTime 1e-8;/; s/^writeInterval .*/writeInterval 5e-9;/' system/controlDict
    mkdir -p "$(dirname $table)"
    printf '(\n (0 0)\n (0.1e-9 5e7)\n (5e-9 5e7)\n (5.1e-9 0)\n (1 0)\n)\n' > $table
    /usr/bin/python3 - "$table" <<'PY'
import re, sys
s = open("0/p").read()
s, n = re.subn(r"uniformValue\s+table\s*\(.*?\n\s*\);",
               'uniformValue tableFile;\n        uniformValueCoeffs { file '
               '"$FOAM_CASE/%s"; }' % sys.argv[1], s, 1, re.S)
assert n == 1
open("0/p", "w").write(s)
PY
    blockMesh > log.blockMesh 2>&1
    cellBlastFoam > log.first 2>&1
    sed -i 's/^endTime .*/endTime 1.5e-8;/' system/controlDict
    if [ $table = tables/pulse.dat ]
    then
        shown="named file tables/pulse.dat (field p, boundaryField/loaded, entry uniformValueCoeffs/file)"
    else
        shown=$table
    fi
    rm -rf "$work/edit"; cp -r "$case" "$work/edit"; cd "$work/edit"
    sed -i 's/5e7)/6e7)/' $table
    caseSums > "$work/before"
    status=0; cellBlastFoam > log.restart 2>&1 || status=$?
    caseSums > "$work/after"
    check "cellBlastFoam, the pulse's tableFile $table edited: refused, naming it, nothing changed" \
        "[ $status -ne 0 ] && grep -q 'would continue the results with other inputs' log.restart \
         && grep -qF '    $shown (changed)' log.restart && cmp -s '$work/before' '$work/after'"
    cd "$case"
    status=0; cellBlastFoam > log.restart 2>&1 || status=$?
    check "cellBlastFoam, the pulse's tableFile $table unchanged: the restart runs" \
        "[ $status -eq 0 ] && grep -q '^End' log.restart && [ -d 1.5e-08 ]"
done

# rhoRiemannFoam
case=$work/fluid
mkdir "$case"; cd "$case"
cp -r "$root/tutorials/verification/waterPulseWall"/{0.orig,system,constant} .
rm -rf constant/polyMesh; cp -r 0.orig 0
sed -i 's/^startFrom .*/startFrom latestTime;/; s/^endTime .*/endTime 1e-8;/; s/^writeInterval .*/writeInterval 5e-9;/' system/controlDict
blockMesh > log.blockMesh 2>&1
rhoRiemannFoam > log.first 2>&1
sed -i 's/^endTime .*/endTime 1.5e-8;/' system/controlDict
refusedAfter "rhoRiemannFoam, water C0" rhoRiemannFoam constant/thermophysicalProperties \
    's/\(C0 *\)[0-9.e+-]*;/\11460;/'
refusedAfter "rhoRiemannFoam, the Riemann solver" rhoRiemannFoam system/fvSolution \
    's/riemannSolver *HLLC;/riemannSolver HLL;/'
# The same entries in another order (fix19d, adv46b d14 (a): refused as
# "constant/thermophysicalProperties (changed)", nothing else named): the
# order named as what differs, nothing changed
rm -rf "$work/edit"; cp -r "$case" "$work/edit"; cd "$work/edit"
sed -i '/^mieGruneisenCoeffs/,/^}/{/rho0/{h;d};/T0/{G}}' \
    constant/thermophysicalProperties
caseSums > "$work/before"
status=0; rhoRiemannFoam > log.restart 2>&1 || status=$?
caseSums > "$work/after"
check "rhoRiemannFoam, mieGruneisenCoeffs reordered: refused, naming the order as what differs, nothing changed" \
    "[ $status -ne 0 ] && grep -qF '    constant/thermophysicalProperties (changed: each of its entries has its recorded value; what differs is their order or an empty sub-dictionary)' log.restart \
     && cmp -s '$work/before' '$work/after'"
cd "$case"
status=0; rhoRiemannFoam > log.restart 2>&1 || status=$?
check "rhoRiemannFoam: the unchanged restart runs" \
    "[ $status -eq 0 ] && grep -q '^End' log.restart && [ -d 1.5e-08 ]"

exit $fail
