#!/bin/bash
# CASETIMEOUT=900
# p08 (new, class 6/2: a file-size limit, `ulimit -f`, SIGXFSZ at a write): (a) bd restarted to 3e-9 under ulimit -f
# N KB where N is just above the largest file bd holds but below solid.h5's size after one more write (the limit hit while
# solid.h5 or a time directory is written); then, without the limit, the restart again: it continues from 2e-09 (or a
# committed 3e-09) and ends; 3e-09/p equals the plain restart's; (b) the smoke indentation (ind) under ulimit -f 64 KB,
# then without it; (c) solidToFoam on bd under ulimit -f 16 KB, then without. Each: the tool stops (a message naming the
# file and the limit, or SIGXFSZ: the OS's kill) and leaves nothing half-written that a later run takes as good; a later
# run that uses a cut file, or results lost = DATALOSS; a signal without a word = CRASH (low).
. "$(dirname "$0")/../lib.sh"
bd; rs; rm -f .runLock; cp -a . $W/b0; tryt 300 "(0) the plain restart to 3e-9 (reference)" cellBlastFoam; cp 3e-09/p $W/p.ref; cd $W; rm -rf blast; cp -a b0 blast; cd blast
big=$(find . -type f -printf '%s\n' | sort -n | tail -1); h5=$(stat -c %s solid/solid.h5); lim=$(( (h5 + 4096) / 1024 + 8 )); echo "   largest file $big B, solid.h5 $h5 B, limit $lim KB"
sums > $W/s0
tryt 300 "(a1) restart to 3e-9 under ulimit -f $lim" bash -c "ulimit -f $lim; exec cellBlastFoam"; echo "   sig lines: $(sig) | last lines: $(tail -2 $W/try.log | tr '\n' '|' | cut -c1-250)"
echo "   after: times $(ls -d [0-9]* .[0-9]* *.incomplete 2>/dev/null | tr '\n' ' ') | solid.h5 steps $(h5steps solid/solid.h5) | tmp files: $(find . -name '*.tmp*' | tr '\n' ' ') | lock: $(lockOf | cut -c1-80)"
tryt 300 "(a2) the restart again without the limit" cellBlastFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | said: $(msg 3 | cut -c1-250)"
[ -f 3e-09/p ] && /usr/bin/python3 -c "
import sys, numpy as np; from neuronFsi import foamField as f
a = np.asarray(f.internalField('3e-09/p')); b = np.asarray(f.internalField(sys.argv[1]))
print('   3e-09/p against the plain restart: largest difference %.3g Pa' % np.abs(a-b).max())" $W/p.ref
echo "   solid.h5 steps $(h5steps solid/solid.h5) (plain restart: 4 expected if 1 per ns and step 0)"
cd $W; ind; tryt 300 "(b1) smoke indentation under ulimit -f 64" bash -c "ulimit -f 64; exec cellIndentationFoam"; echo "   sig lines: $(sig) | last: $(tail -2 $W/try.log | tr '\n' '|' | cut -c1-250)"; after
rm -f .runLock; latest; tryt 600 "(b2) again without the limit (startFrom latestTime)" cellIndentationFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | said: $(msg 3 | cut -c1-250)"; after
cd $W; rm -rf blast; cp -a b0 blast; cd blast; rm -rf constant/solid; tryt 120 "(c1) solidToFoam under ulimit -f 16" bash -c "ulimit -f 16; exec solidToFoam solid/solid.h5"; echo "   sig lines: $(sig) | last: $(tail -2 $W/try.log | tr '\n' '|' | cut -c1-250) | constant/solid: $(ls constant/solid 2>/dev/null | tr '\n' ' ' | cut -c1-100)"
tryt 120 "(c2) solidToFoam again without the limit" solidToFoam solid/solid.h5; echo "   $(tail -1 $W/try.log | cut -c1-200)"
