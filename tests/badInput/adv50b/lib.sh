# lib.sh (adv50b): adv49b's lib.sh (tests/badInput/adv49b, and through it every helper of adv35-adv49b: bd, rs, idn, ik,
# q, qEnd, qrun, sbd, pbd, blast/blastDone, prev/PREV, MYPREV, blastEnd, latest, restart0, sums, changed, nochange, kept,
# where, tryf, tryt, try, run, fatal, waitFor, sameSeries, cmpRef, closeTo, study, setStudy, cal, flip, nul, h5same,
# h5steps, xmfsteps, marks, lockOf, sete, dupe, inDir, killIn, after, cont, forceOk, short, nLines, fsiSet, cm, mdir,
# mset, fset, e6, rs6, fresh, away ...). runOne.sh's ADV=<prefix>adv50b is mapped to <prefix>adv49b, which adv49b's lib.sh
# maps on to <prefix>adv47b: every base (adv46b's bd, idn; adv47b's q; mine below) lies in that one folder, built once by
# prebuild.sh. Plus (mine):
#   qm [FLUID] [HEX]  mdir quarter3D with the smoke sizes of adv47b's QOPT (cell 1.4/1.4/1 um; water box 30 um, near 1 um,
#                     far 5 um, axial 1 um, lateral 2 um) in cellMeshDict.allrun; FLUID: more entries of fluid{}, HEX: more
#                     entries of hexCoeffs{} (text, e.g. "oGrid orthogonal;")
#   msh               md5 of constant/cell.msh and constant/fluid.msh (one line)
#   cmk LABEL [OPT]   cm, then whether the meshes of the case changed since the last `msh` kept in $W/msh0 ("meshes kept" /
#                     "meshes CHANGED")
#   pwd0              a finished blast preview (bd) with planeWave run on it (postProcessing/planeWave/0/reference.dat),
#                     base pwBase, cd there
#   prj               $W/proj: a copy of the project whose tutorials/ is copied and every other top-level entry a link
#                     (the main job tutorials/Allrun runs there without touching the worktree's tutorials), cd there
#   pyw               /usr/bin/python3 (the interpreter the scripts' #! names: numpy, h5py)
#   iw ARGS...        bench/blast/analysis/incidentWindow.py ARGS under a 120 s KILL timeout (tryt)
# At the case's exit $W is removed (my cases keep nothing under /tmp; the outputs are the case's own text).
ADV=${ADV:-/tmp/adv50b-adv50b}; ADV=${ADV%adv50b}adv49b
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv49b/lib.sh"
trap 'unmountAll; cd /; [ -n "${KEEPW:-}" ] || rm -rf "$W"' EXIT
qm() { mdir quarter3D; printf 'nucleusSize 1.4e-6;\ncytoplasmSize 1.4e-6;\nmembraneSize 1e-6;\n' > system/cellMeshDict.allrun
  /usr/bin/python3 - "${1:-}" "${2:-}" >> system/cellMeshDict.allrun <<'Q'
import re, sys
def merge(defaults, extra):
    keys = set(re.findall(r'(?:^|;)\s*(\w+)\s', extra))
    kept = [e.strip() + ';' for e in defaults.split(';') if e.strip() and e.split()[0] not in keys]
    return ' '.join(kept) + (' ' + extra if extra else '')
f = merge('nearSize 1e-6; farSize 5e-6; boxSize 30e-6; growthDistance 20e-6', sys.argv[1])
h = merge('axialSize 1e-6; lateralSize 2e-6', sys.argv[2])
print('fluid { %s hexCoeffs { %s } }' % (f, h))
Q
}
msh() { echo "$(md5sum constant/cell.msh 2>/dev/null | cut -c1-8) $(md5sum constant/fluid.msh 2>/dev/null | cut -c1-8)"; }
cmk() { msh > $W/msh0; local l=$1; shift; cm "$@"; echo "   $l: $( [ "$(msh)" = "$(cat $W/msh0)" ] && echo 'meshes kept' || echo "meshes CHANGED ($(cat $W/msh0) -> $(msh))")"; }
pwdDone_() { blastDone; timeout -s KILL 900 planeWave -case . > log.planeWave 2>&1 || { echo "pwd0: planeWave failed"; tail -3 log.planeWave; }; }
pwd0() { mkBase_ pwBase pwdDone_ blast; cp -a $ADV/pwBase $W/pw; cd $W/pw; }
prj() { mkdir -p $W/proj; local e; for e in "$ROOT"/* "$ROOT"/.git*; do [ "$(basename $e)" = tutorials ] && continue; ln -s "$e" $W/proj/; done
  cp -r "$ROOT/tutorials" $W/proj/; cd $W/proj; }
pyw() { /usr/bin/python3 "$@"; }
iw() { tryt 120 "incidentWindow $*" /usr/bin/python3 "$ROOT/bench/blast/analysis/incidentWindow.py" "$@"; }
#   vals FILE KEY V... -- CMD...   for each V: the original FILE back, the first "KEY ...;" of FILE set to V (sete), CMD under
#                     a 150 s KILL timeout (tryt); what an accepted run wrote is named, then removed; FILE restored at the end
vals() { local f=$1 k=$2; shift 2; local vs=(); while [ $# -gt 0 ] && [ "$1" != "--" ]; do vs+=("$1"); shift; done; shift
  cp "$f" $W/vals.orig; local v; for v in "${vs[@]}"; do cp $W/vals.orig "$f"; sete "$f" "$k" "$v" > /dev/null || { echo "   vals: no $k in $f"; continue; }
    tryt 150 "$k = $v" "$@"; [ -d 1e-11 ] || [ -d 2e-11 ] || [ -d solid ] && echo "      (ran: $(ls -d [1-9]* solid 2>/dev/null | tr '\n' ' '))"; rm -rf [1-9]* solid postProcessing .*overwritten* constant/solid; done; cp $W/vals.orig "$f"; }
#   sb                a fresh copy of the prepared preview (blast: no results) with endTime 2e-11, writeInterval 1e-11 (short)
sb() { blast; short; }
#   mv_ KEY V...      cellMesh in the current mdir/qm folder for each V of KEY (mset; KEY's line removed again after), meshes
#                     of a first good run kept: "meshes kept/CHANGED" per value
mv_() { local k=$1; shift; cm > /dev/null; [ -f constant/cell.msh ] || { echo "   mv_: the good mesh was not written: $(tail -2 $W/try.log | tr '\n' ' ')"; }; cp system/cellMeshDict.allrun $W/mv.orig
  local v; for v in "$@"; do cp $W/mv.orig system/cellMeshDict.allrun; mset "$k" "$v"; cmk "$k $v"; done; cp $W/mv.orig system/cellMeshDict.allrun; }
#   fsiSet K V        (replaces adv49b's, whose sed added "K V;" after every "{" line up to coupling: FoamFile{}, interface{}
#                     and coupling{}) the first "K ...;" of constant/fsiProperties set, else "K V;" added inside coupling{} only
fsiSet() { sete constant/fsiProperties "$1" "$2" > /dev/null 2>&1 || /usr/bin/python3 - constant/fsiProperties "$1" "$2" <<'P'
import re, sys
p, k, v = sys.argv[1:4]; t = open(p).read(); m = re.search(r'^coupling\s*\{', t, re.M)
open(p, 'w').write(t[:m.end()] + '\n    %s %s;' % (k, v) + t[m.end():])
P
  grep -n "^ *$1 " constant/fsiProperties | head -2 | sed 's/^/   fsiProperties: /'; }
#   killAll DIR       killIn DIR repeated (at most 10 times, 0.5 s apart) until no process has its working directory under DIR
#                     (a script killed between two of its steps may have started the next one meanwhile)
killAll() { local i; for i in 1 2 3 4 5 6 7 8 9 10; do killIn "$1"; sleep 0.5; [ -z "$(inDir "$1")" ] && return 0; done; echo "   killAll: still running: $(inDir "$1")"; }
