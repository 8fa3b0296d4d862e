#!/bin/bash
# CASETIMEOUT=900
# n40 (new, class 2: n14's hard-linked copy through our other writers - fluidWedgeMesh.py and solidToFoam - as a
# regression check of fix19k's writers): bd converted once (solidToFoam: 1e-09/solid, 2e-09/solid, constant/solid/polyMesh
# in the original A); A copied with cp -al to C; in C: (a) fluidWedgeMesh.py -h 0.3e-6 ... -o system/blockMeshDict;
# (b) the pulse doubled in 0/p, `cellBlastFoam -overwrite` (new results in C), then `solidToFoam solid/solid.h5`. Then
# A's system/blockMeshDict, A's 1e-09/solid/*, 2e-09/solid/*, constant/solid/polyMesh/* against their md5 before.
# Expected: A unchanged (every writer writes aside and renames, or removes the link first); A's files rewritten through
# the shared inodes = DATALOSS (A's converted fields then show C's run).
. "$(dirname "$0")/../lib.sh"
bd; tryt 300 "(0) solidToFoam in A" solidToFoam solid/solid.h5; A=$PWD; md5sum system/blockMeshDict [12]e-09/solid/* constant/solid/polyMesh/* 2>/dev/null > $W/mA; echo "   A: $(wc -l < $W/mA) files recorded"
cd $W; cp -al $A $W/C; cd $W/C
tryt 120 "(a) fluidWedgeMesh.py -h 0.3e-6 in the cp -al copy" /usr/bin/python3 $ROOT/tutorials/blast/fluidWedgeMesh.py -h 0.3e-6 -far 2e-6 -Z 20e-6 -o system/blockMeshDict; echo "   said: $(say 1 | cut -c1-200)"
/usr/bin/python3 - 0/p <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read()
def dbl(m):
    return "(%s %s)" % (m.group(1), repr(2 * float(m.group(2))) if float(m.group(2)) > 1e6 else m.group(2))
open(p + ".new", "w").write(re.sub(r"\(\s*([-+0-9.eE]+)\s+([-+0-9.eE]+)\s*\)", dbl, t))
P
mv 0/p.new 0/p; rm -f .runLock; tryt 300 "(b) cellBlastFoam -overwrite in the copy (pulse doubled)" cellBlastFoam -overwrite; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-200)"
tryt 300 "(b) solidToFoam in the copy" solidToFoam solid/solid.h5; echo "   said: $(say 2 | cut -c1-200)"
cd $A; echo "   A after: $(md5sum -c $W/mA 2>/dev/null | grep -v ': OK$' | tr '\n' ' ' | cut -c1-500)"; echo "   A unchanged: $(md5sum -c $W/mA 2>/dev/null | grep -c ': OK$') of $(wc -l < $W/mA)"
