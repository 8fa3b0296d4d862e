# lib.sh (adv49b): adv48b's lib.sh (tests/badInput/adv48b, and through it every helper of adv35-adv48b: bd, rs, idn, ik,
# pbd, ibd, blast/blastDone, prev/PREV, blastEnd, latest, restart0, sums, changed, nochange, kept, where, tryf, tryt, try,
# run, fatal, waitFor, sameSeries, cmpRef, closeTo, study, setStudy, cal, flip, nul, h5same, h5steps, xmfsteps, marks,
# lockOf, sete, dupe, inDir, killIn, after, cont, forceOk, short, nLines ...). runOne.sh's ADV=<prefix>adv49b is mapped to
# <prefix>adv48b, which adv48b's lib.sh maps to <prefix>adv47b: the bases (adv47b's and adv48b's and mine, prebuild.sh)
# lie in that one folder. Plus (mine, built once by prebuild.sh, copied with cp -a):
#   MYPREV   $PREV with a 14 um column (-Z 14e-6): the pulse reaches the cell's top at about 4 ns, so that a run to 5-6 ns
#            loads the solid (the 20 um column of $PREV reaches it after 8 ns)
#   sbd      the preview prepared by its Allrun with -meshType structured ($MYPREV -endTime 5e-9 -noRun), run to 5e-9
#            (writes every 1 ns)
#   xbd      the same with the default meshType and -predictor extrapolated, run to 5e-9
#   mbd      the same with -membraneLayers 2 -solidSubcycles 4 (the solid's step the smaller one: subcycles active), to 5e-9
#   fresh    in a copy of a finished base: its results removed (postProcessing solid time dirs), startFrom startTime
#   rs6      startFrom latestTime, endTime 6e-9 (the controlDict.allrun's other lines kept)
#   e6       endTime 6e-9 in controlDict.allrun (a straight run from 0 to 6e-9 after fresh)
#   fsiSet K V   the first "K ...;" of constant/fsiProperties set (sete), else K V; added inside coupling{}
#   cm           cellMesh under a 300 s KILL timeout with /usr/bin/time (maxRSS), output in $W/try.log like tryt
#   lockLine     a lock's lines as the solver writes them (printed by the case when it looks at one)
ADV=${ADV:-/tmp/adv49b-adv49b}; ADV=${ADV%adv49b}adv48b
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv48b/lib.sh"
MYPREV="-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 14e-6 -writeInterval 1e-9 -noPlots -noVTK"
prepDone_() { prev; ./Allrun $MYPREV -endTime 5e-9 -noRun "$@" > log.prep 2>&1 || { echo "prep failed ($*)"; tail -5 log.prep; }
  cellBlastFoam > log.first 2>&1 || { echo "run failed ($*)"; tail -5 log.first; }; mv $W/c $W/blast; }
sbdDone_() { prepDone_ -meshType structured; }
xbdDone_() { prepDone_ -predictor extrapolated; }
mbdDone_() { prepDone_ -membraneLayers 2 -solidSubcycles 4; }
sbd() { mkBase_ sbdBase sbdDone_ blast; cp -a $ADV/sbdBase $W/sblast; cd $W/sblast; }
xbd() { mkBase_ xbdBase xbdDone_ blast; cp -a $ADV/xbdBase $W/xblast; cd $W/xblast; }
mbd() { mkBase_ mbdBase mbdDone_ blast; cp -a $ADV/mbdBase $W/mblast; cd $W/mblast; }
fresh() { rm -rf postProcessing solid [1-9]* .*overwritten*; restart0; }
e6() { sed -i '/^endTime/d' system/controlDict.allrun; echo 'endTime 6e-9;' >> system/controlDict.allrun; }
rs6() { latest; e6; }
fsiSet() { sete constant/fsiProperties "$1" "$2" > /dev/null 2>&1 || sed -i "0,/^coupling/{n;s/^{/{\n    $1 $2;/}" constant/fsiProperties; grep -n "^ *$1 " constant/fsiProperties | head -2 | sed 's/^/   fsiProperties: /'; }
cm() { timeout -s KILL ${2:-300} /usr/bin/time -f 'maxRSS %M kB, %e s wall, %U s user CPU' cellMesh ${1:-} > $W/try.log 2>&1; local rc=$?; echo "cellMesh ${1:-}: rc=$rc | $(grep -a -m1 -A3 'FATAL\|error:\|Error\|Traceback\|refused\|[Rr]efus' $W/try.log | grep -av '^ *$\|^-->\|From function\|^\[.\] *$' | head -3 | tr '\n' ' ' | cut -c1-420) | $(tail -1 $W/try.log)"; }
#   mdir [MODE]  $W/m: an empty case with the preview's system/cellMeshDict (MODE axisymmetric) or the quarter's (quarter3D)
#                and coarse sizes (0.5 um cell, 0.4 um membrane) in cellMeshDict.allrun; cd there
#   mset K V     K V; in system/cellMeshDict.allrun (its earlier K line removed; read last: replaces the dictionary's value)
mdir() { rm -rf $W/m; mkdir -p $W/m/constant; cd $W/m; if [ "${1:-axisymmetric}" = quarter3D ]; then cp -r "$ROOT/tutorials/blast/quarter3D/system" .; else cp -r "$ROOT/tutorials/blast/axisymmetricPreview/system" .; fi
  rm -f system/*.allrun; grep -q 'cellMeshDict.allrun' system/cellMeshDict || echo '#sinclude "cellMeshDict.allrun"' >> system/cellMeshDict
  printf 'nucleusSize 0.5e-6;\ncytoplasmSize 0.5e-6;\nmembraneSize 0.4e-6;\n' > system/cellMeshDict.allrun; }
mset() { sed -i "/^$1 /d" system/cellMeshDict.allrun; echo "$1 $2;" >> system/cellMeshDict.allrun; }
#   cmp6 REF     this case against REF after runs to 6e-9: the four logs (sameSeries), solid.h5 (h5same), 6e-09/p (cmp)
#   away NAME    cd $W and move the current case folder to $W/NAME (kept for a later comparison)
cmp6() { echo "   vs $(basename $1): $(sameSeries $1 | awk '{print $1, $2}' | tr '\n' ' ')| solid.h5 $(h5same solid/solid.h5 $1/solid/solid.h5) | 6e-09/p $(cmp -s 6e-09/p $1/6e-09/p && echo same || echo DIFF)"; }
away() { local d=$PWD; cd $W; mv "$d" $W/$1; }
#   fset FILE WHERE I VALUE...  a value of an OpenFOAM field file set in place, ascii or binary: WHERE = internal (the
#                internalField) or a patch name (its `value` list); I = the cell/face index (-1: every one); VALUE... one
#                number (scalar) or three (vector), or xF: the value there multiplied by F; prints what it changed
fset() { /usr/bin/python3 - "$@" <<'P'
import re, struct, sys
p, where, i, sv = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4:]
vals = [float(v[1:]) if v.startswith('x') else float(v) for v in sv]; mul = [v.startswith('x') for v in sv]
b = open(p, 'rb').read()
if where == 'internal':
    k = b.index(b'internalField')
else:
    k = b.index(b'boundaryField'); k = re.compile(rb'\b' + re.escape(where.encode()) + rb'\s*\{').search(b, k).end(); k = b.index(b'value', k)
m = re.compile(rb'(uniform|nonuniform\s+List<(scalar|vector)>\s*(\d+)\s*\()').search(b, k)
if m.group(1) == b'uniform' or not m.group(2):
    print('   fset: %s %s is uniform, not a list' % (p, where)); sys.exit(1)
n, vec, s = int(m.group(3)), m.group(2) == b'vector', m.end()
w = 3 if vec else 1
binary = b'format      binary' in b[:800] or b'format binary' in b[:800] or not re.match(rb'\s*[-+0-9.(]', b[s:s+40])
if binary:
    raw = bytearray(b[s:s + 8 * w * n]); idx = range(n) if i < 0 else [i]
    for c in idx:
        for j in range(w):
            v = vals[j] if len(vals) > j else vals[0]; old = struct.unpack_from('<d', raw, 8 * (w * c + j))[0]
            struct.pack_into('<d', raw, 8 * (w * c + j), old * v if mul[min(j, len(mul) - 1)] else v)
    b = b[:s] + bytes(raw) + b[s + 8 * w * n:]
else:
    e = b.index(b'\n)', s); body = b[s:e].decode().split('\n'); items = [x for x in body if x.strip()]
    idx = range(n) if i < 0 else [i]
    fmt = (lambda: '(' + ' '.join(repr(v) for v in vals[:3]) + ')') if vec else (lambda: repr(vals[0]))
    for c in idx: items[c] = fmt()
    b = b[:s] + ('\n' + '\n'.join(items)).encode() + b[e:]
open(p, 'wb').write(b); print('   fset: %s %s[%s] = %s (%s, %d values)' % (p, where, 'all' if i < 0 else i, vals, 'binary' if binary else 'ascii', n))
P
}
