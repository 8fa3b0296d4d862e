# lib.sh (adv47b): adv46b's lib.sh (tests/badInput/adv46b: every helper of adv35-adv46b: bd, rs, idn, ik, tryt, after, cont,
# ind/indDone, indKilled, blast/blastDone, latest, blastEnd, sums, changed, nochange, kept, where, tryf, try, run, fatal,
# waitFor, sameSeries, study, setStudy, cal, prev/PREV, flip, h5same, h5steps, xmfsteps, marks, lockOf, ro, tiny, ODD, sete,
# dupe, inDir, killIn ...) with ADV defaulting to /tmp/adv47b-adv47b, plus (bases built once by prebuild.sh, copied by cp -a):
#   bd2     a finished blast preview as bd but with the pulse table of 0/p scaled by 2 (another run of the same case files
#           but 0/p), cd there
#   q       the 3D quarter (tutorials/blast/quarter3D, Allrun -np 2 with the small sizes of QOPT, -noRun), writeInterval 1e-9,
#           run on 2 ranks to 2e-9 (processor0/1 hold 1e-09, 2e-09), cd there; qEnd END: endTime END (controlDict.allrun)
#   qrun N  mpirun -np N cellBlastFoam -parallel (output in $W/try.log through tryt)
#   lk      the lock's first line (pid / executable)
ADV=${ADV:-/tmp/adv47b-adv47b}
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv46b/lib.sh"
bd2Done_() { blast; /usr/bin/python3 - 0/p <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read()
# the pulse table's pressures (second number of each (t p) pair) doubled, the ambient row (p = ambient) kept as is
def dbl(m):
    return "(%s %s)" % (m.group(1), repr(2 * float(m.group(2))) if float(m.group(2)) > 1e6 else m.group(2))
n = re.sub(r"\(\s*([-+0-9.eE]+)\s+([-+0-9.eE]+)\s*\)", dbl, t)
print("bd2: 0/p pulse rows changed:", sum(1 for a, b in zip(t.split("\n"), n.split("\n")) if a != b)); open(p, "w").write(n)
P
  cellBlastFoam > log.first 2>&1 || { echo "bd2Done failed"; tail -3 log.first; }; }
bd2() { mkBase_ bd2Base bd2Done_ blast; cp -a $ADV/bd2Base $W/blast2; cd $W/blast2; }
QOPT="-np 2 -box 30e-6 -h 1e-6 -dz 1e-6 -lateral 2e-6 -far 5e-6 -endTime 2e-9 -noPlots"
qEnd() { sed -i "/^endTime\|^writeInterval/d" system/controlDict.allrun; printf 'endTime %s;\nwriteInterval %s;\n' "$1" "${2:-1e-9}" >> system/controlDict.allrun; }
qDone_() { cp -r "$ROOT/tutorials/blast/quarter3D" $W/q; cd $W/q; ./Allclean > /dev/null 2>&1; ./Allrun $QOPT -noRun > log.prep 2>&1 || { echo "qDone: Allrun failed"; tail -5 log.prep; }
  qEnd 2e-9; mpirun -np 2 cellBlastFoam -parallel > log.first 2>&1 || { echo "qDone: run failed"; tail -5 log.first; }; }
q() { mkBase_ qBase qDone_ q; cp -a $ADV/qBase $W/q; cd $W/q; }
qrun() { local n=$1; shift; mpirun -np $n cellBlastFoam -parallel "$@"; }
lk() { head -c 300 .runLock 2>/dev/null | tr '\n' ';' || echo "(no lock)"; }
