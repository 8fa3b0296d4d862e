#!/bin/bash
# CASETIMEOUT=900
# l31 (new, class 6/4: an input file that is huge - a sparse file, as a failed copy or a truncate -s leaves; fix19j item 1
# asks for a size limit per kind before reading): 1 GiB sparse files (zeros; truncate -s 1G) as (a) constant/fsiProperties
# (sb), (b) constant/cell.msh (sb), (c) constant/indenterProperties (ind), (d) the exactRiemann case file, (e)
# postProcessing/planeWave/0/reference.dat read by incidentWindow.py (pwd0), (f) planeWave -reference FILE, (g)
# system/cellMeshDict (qm). Each under /usr/bin/time, ulimit -v 3 GB and a 120 s KILL timeout (the first run, 4 GiB
# files without a memory limit, was stopped by hand after (d): cellBlastFoam took 8 GB RSS and 100 s on (a), the shared
# machine had 5 GB left; out/B/adv53_l31.first.txt.keep). Expected: refused before reading, naming
# the file and its size; reading 1 GiB for minutes (no end at 120 s) = HANG; a MemoryError traceback or bad_alloc = CRASH.
. "$(dirname "$0")/../lib.sh"
one() { tryt 120 "$1" bash -c 'ulimit -v 3000000; exec /usr/bin/time -f "maxRSS %M kB, %e s" "$@"' _ "${@:2}"; echo "   said: $(say 2 | cut -c1-250) | $(tail -1 $W/try.log | cut -c1-80)"; }
big() { rm -f "$1"; truncate -s 1G "$1"; }
sb; cp -a . $W/b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
big constant/fsiProperties; one "(a) constant/fsiProperties 1 GiB of zeros" cellBlastFoam; back
big constant/cell.msh; one "(b) constant/cell.msh 1 GiB of zeros" cellBlastFoam; back
cd $W; ind; big constant/indenterProperties; one "(c) constant/indenterProperties 1 GiB" cellIndentationFoam
cd $W; big $W/c.case; one "(d) exactRiemann case file 1 GiB" $ROOT/build/bin/exactRiemann $W/c.case n=11; rm -f $W/c.case
cd $W; pwd0; big postProcessing/planeWave/0/reference.dat; one "(e) reference.dat 1 GiB: incidentWindow.py" /usr/bin/python3 $ROOT/bench/blast/analysis/incidentWindow.py .
big $W/ref.big; one "(f) planeWave -check -reference 1 GiB" planeWave -case . -check -reference $W/ref.big; rm -f $W/ref.big
cd $W; qm; big system/cellMeshDict; one "(g) system/cellMeshDict 1 GiB" cellMesh
