#!/bin/bash
# CASETIMEOUT=900
# l12 (new, class 4/6: adv52 p10's FIFO and device for the other readers - OpenFOAM's dictionaries, our gmsh reader, the
# inflow table, the pulse's tableFile, the Python readers): a FIFO with no writer (or /dev/zero by a link) as
# (a) constant/fsiProperties, (b) constant/cell.msh (sb), (c) the 0/p pulse's tableFile, (d) system/cellMeshDict (cellMesh,
# qm), (e) constant/indenterProperties (ind), (f) reference.dat read by incidentWindow.py (pwd0), (g) planeWave -reference
# FIFO, (h) constant/cell.msh -> /dev/zero (a link). Each under a 40 s KILL timeout. Expected: refused naming the file (not a
# regular file) rc != 0; no end at 40 s = HANG; a traceback = CRASH (low).
. "$(dirname "$0")/../lib.sh"
one() { tryt 40 "$1" "${@:2}"; echo "   said: $(say 2 | cut -c1-250) | $( [ $(grep -a -c . $W/try.log) -eq 0 ] && echo '(no output)' )"; }
sb; cp -a . $W/b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
rm constant/fsiProperties; mkfifo constant/fsiProperties; one "(a) constant/fsiProperties a FIFO" cellBlastFoam; back
rm constant/cell.msh; mkfifo constant/cell.msh; one "(b) constant/cell.msh a FIFO" cellBlastFoam; back
rm constant/cell.msh; ln -s /dev/zero constant/cell.msh; one "(h) constant/cell.msh a link to /dev/zero" cellBlastFoam; back
/usr/bin/python3 - 0/p <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read(); i = t.index('boundaryField'); m = re.search(r'(uniformValue\s+)(table\s*\(.*?\)\s*\)\s*;|table[^;]*;)', t[i:], re.S)
if m:
    a, b = i + m.start(2), i + m.end(2); t = t[:a] + 'tableFile;\n        uniformValueCoeffs { file "$FOAM_CASE/pulse.dat"; }' + t[b:]; open(p, 'w').write(t); print('   0/p: the pulse table now tableFile $FOAM_CASE/pulse.dat')
else: print('   0/p: no uniformValue table found')
P
mkfifo pulse.dat; one "(c) the pulse's tableFile a FIFO" cellBlastFoam; back
cd $W; qm; rm system/cellMeshDict; mkfifo system/cellMeshDict; one "(d) system/cellMeshDict a FIFO" cellMesh
cd $W; ind; rm constant/indenterProperties; mkfifo constant/indenterProperties; one "(e) constant/indenterProperties a FIFO" cellIndentationFoam
cd $W; pwd0; R=postProcessing/planeWave/0/reference.dat; rm $R; mkfifo $R; one "(f) reference.dat a FIFO: incidentWindow.py" /usr/bin/python3 $ROOT/bench/blast/analysis/incidentWindow.py .
mkfifo $W/ref.fifo; one "(g) planeWave -check -reference FIFO" planeWave -case . -check -reference $W/ref.fifo
