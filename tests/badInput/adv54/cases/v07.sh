#!/bin/bash
# CASETIMEOUT=600
# v07 (fix19j row "a user's file that is no regular file or beyond any sane size", varied: other readers, the limits'
# edges, other kinds), each under `ulimit -v 3000000` (3 GB) and a 60 s KILL: (a) constant/indenterProperties a sparse
# file of 64 MiB + 1 byte (the dictionary limit + 1) and of exactly 64 MiB of spaces-and-newlines-free zeros:
# cellIndentationFoam; (b) system/riemannProblemDict a FIFO: setRiemannProblem; (c) 0/T's top a uniformFixedValue
# tableFile naming /dev/urandom (a device): the short preview; (d) force.dat a FIFO and a 1.5 GiB sparse force.dat
# (above the 1 GiB table limit): plotIndentation.py; (e) solid/solid.h5 a FIFO and a link to /dev/zero: solidToFoam;
# (f) planeWave -reference on a 2 GiB sparse file (adv53 l31 (e): 1 GiB read before its refusal); (g) a 300 MiB sparse
# constant/cell.msh (the mesh limit 256 MiB): cellBlastFoam restart. Expected: each refused at once naming the file, its
# kind or size and the limit; an endless wait = HANG, a signal/traceback = CRASH, a read of GBs before the refusal = low.
. "$(dirname "$0")/../lib.sh"
vt() { local l=$1; shift; local t0=$(date +%s.%N); tryt 60 "$l" bash -c 'ulimit -v 3000000; exec "$@"' _ "$@"; echo "   $(echo "$(date +%s.%N) - $t0" | bc | cut -c1-5) s | sig $(sig) | said: $(say 2 | cut -c1-260)"; }
ind; cp constant/indenterProperties $W/ip; truncate -s $((64*1024*1024 + 1)) constant/indenterProperties; vt "(a) indenterProperties 64 MiB + 1 B (sparse zeros)" cellIndentationFoam
cp $W/ip constant/indenterProperties; truncate -s $((64*1024*1024)) constant/indenterProperties; vt "(a2) indenterProperties the valid dictionary padded with zeros to exactly 64 MiB" cellIndentationFoam
cd $W; sod; mv system/riemannProblemDict $W/rpd; mkfifo system/riemannProblemDict; vt "(b) riemannProblemDict a FIFO" setRiemannProblem
cd $W; sb; /usr/bin/python3 - 0/T <<'P'
import sys, re
p = sys.argv[1]; t = open(p).read()
m = re.search(r'\n(\s*)top\s*\{[^}]*\}', t)
new = '\n    top\n    {\n        type uniformFixedValue;\n        uniformValue tableFile;\n        uniformValueCoeffs { file "/dev/urandom"; }\n        value uniform 293.15;\n    }'
print("   0/T top was:", m.group(0).strip().replace("\n", " ")[:120] if m else "none (the '.*' entry: top added before it)")
t = t[:m.start()] + new + t[m.end():] if m else t.replace("boundaryField\n{", "boundaryField\n{" + new, 1); open(p, "w").write(t)
P
vt "(c) 0/T top tableFile /dev/urandom" cellBlastFoam
cd $W; rm -rf ind; idn; d=postProcessing/indentation; mv $d/force.dat $W/fd; mkfifo $d/force.dat; vt "(d) force.dat a FIFO: plotIndentation.py" /usr/bin/python3 $ROOT/tutorials/indentation/plotIndentation.py .
rm $d/force.dat; cp $W/fd $d/force.dat; truncate -s 1610612736 $d/force.dat; vt "(d2) force.dat 1.5 GiB sparse: plotIndentation.py" /usr/bin/python3 $ROOT/tutorials/indentation/plotIndentation.py .
vt "(d3) the same with -acceptHandMade" /usr/bin/python3 $ROOT/tutorials/indentation/plotIndentation.py -acceptHandMade .
cd $W; rm -rf blast; bd; mv solid/solid.h5 $W/s.h5; mkfifo solid/solid.h5; vt "(e) solid.h5 a FIFO: solidToFoam" solidToFoam solid/solid.h5; rm solid/solid.h5; ln -s /dev/zero solid/solid.h5; vt "(e2) solid.h5 a link to /dev/zero: solidToFoam" solidToFoam solid/solid.h5
rm solid/solid.h5; mv $W/s.h5 solid/solid.h5; truncate -s 2147483648 $W/big.dat; vt "(f) planeWave -reference a 2 GiB sparse file" planeWave -case . -reference $W/big.dat; rm -f $W/big.dat
cp constant/cell.msh $W/cm; truncate -s $((300*1024*1024)) constant/cell.msh; rs; rm -f .runLock; vt "(g) cell.msh 300 MiB (sparse tail): the restart" cellBlastFoam
