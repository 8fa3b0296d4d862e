# lib.sh: shared by the adv35 reproducers. Sets the environment of the
# project build ROOT (default /work/wt-adv35), builds the two base cases
# once under $ADV (default /tmp/adv35; remove it to rebuild the bases with another build) and gives fresh copies:
#   ind      a copy of the smoke indentation case (mesh, no results), cd there
#   indDone  the same, run to its end (4 protocol rows)
#   blast    a copy of the prepared blast preview (20 um column, 2 ns, writes every 1 ns)
#   blastDone  the same, run to its end
here_=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
if [ -z "${ROOT:-}" ]; then
    # committed copy: tests/badInput/adv35/lib.sh in the project; notes copy: the adv35 worktree
    if [ -f "$here_/../../../etc/bashrc" ]; then ROOT=$(cd "$here_/../../.." && pwd); else ROOT=/work/wt-adv35; fi
fi
ADV=${ADV:-/tmp/adv35}
. "$ROOT/etc/bashrc"
mkdir -p "$ADV"
if [ ! -f "$ADV/indBase/constant/cell.msh" ]; then
    rm -rf "$ADV/indBase"
    cp -r "$ROOT/tutorials/indentation/averageCell" "$ADV/indBase"
    (cd "$ADV/indBase" && /usr/bin/python3 "$ROOT/tests/lib/setProtocol.py" \
        constant/indenterProperties --smoke && cellMesh > log.cellMesh 2>&1)
fi
if [ ! -f "$ADV/blastBase/axisymmetricPreview/constant/cell.msh" ]; then
    bash "$ROOT/tests/blast/runPreview.sh" "$ADV/blastBase" -h 0.25e-6 -far 2e-6 \
        -cell 0.5e-6 -Z 20e-6 -endTime 2e-9 -writeInterval 1e-9 -noPlots -noRun \
        > "$ADV/blastBase.log" 2>&1
fi
W=$(mktemp -d "$ADV/w.XXXXXX")
ind() { mkdir -p "$W/ind"; cp -r "$ADV/indBase"/{system,constant} "$W/ind/"; cd "$W/ind"; }
indDone() { ind; cellIndentationFoam > log.first 2>&1 || { echo "indDone failed"; tail -3 log.first; }; }
blast() { cp -r "$ADV/blastBase/axisymmetricPreview" "$W/blast"; cd "$W/blast"; rm -rf postProcessing solid [1-9]*; }
blastDone() { blast; cellBlastFoam > log.first 2>&1 || { echo "blastDone failed"; tail -3 log.first; }; }
setd() { foamDictionary -entry "$2" -set "$3" "$1" > /dev/null; }   # setd FILE ENTRY VALUE
sums() { find . -type f ! -name 'log.*' ! -name '.runLock' -print0 | sort -z | xargs -0 md5sum; }
# sod: a copy of tutorials/verification/sodIdealGas with its mesh and initial state (setRiemannProblem), cd there
sod() { cp -r "$ROOT/tutorials/verification/sodIdealGas" "$W/sod"; cd "$W/sod"; ./Allclean > /dev/null 2>&1; cp -r 0.orig 0; blockMesh > log.blockMesh 2>&1; setRiemannProblem > log.setRiemannProblem 2>&1 || echo "setRiemannProblem failed"; }
sodDone() { sod; rhoRiemannFoam > log.first 2>&1 || { echo "sodDone failed"; tail -3 log.first; }; }
