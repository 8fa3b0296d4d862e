#!/bin/bash
# CASETIMEOUT=900
# p17 (new, class 5: outputs swapped between ranks, a result file's sidecar edited): pbd (2 ranks, 2e-09 on both)
# restarted to 3e-9 after (a) processor0/2e-09 and processor1/2e-09 swapped (each whole and committed, but the other
# rank's), (b) only their .writeCommitted markers swapped, (c) processor1/2e-09/uniform swapped with processor0's;
# (d) bd's solid/solid.xmf with a step's time edited (1e-09 -> 1.5e-09) and a step removed, then solidToFoam and the
# restart to 3e-9 (is the XDMF file, which ParaView reads, checked or rewritten?). Expected: (a)-(c) refused naming the
# rank and file; (d) the .xmf named as not matching solid.h5, or rewritten from it; a restart that continues from swapped
# ranks = SILENT; an .xmf left wrong without a word = SILENT (low).
. "$(dirname "$0")/../lib.sh"
pbd; rs; rm -f .runLock; cd $W; mv pblast b0; again() { cd $W; rm -rf pblast; cp -a b0 pblast; cd pblast; }
one() { tryt 200 "$1" mpirun -np 2 cellBlastFoam -parallel; echo "   End: $(grep -a -c '^End' $W/try.log) | sig: $(sig) | said: $(msg 5 | cut -c1-350)"; }
again; mv processor0/2e-09 $W/t0; mv processor1/2e-09 processor0/2e-09; mv $W/t0 processor1/2e-09; one "(a) processor0/2e-09 and processor1/2e-09 swapped"
again; mv processor0/2e-09/.writeCommitted $W/m0; mv processor1/2e-09/.writeCommitted processor0/2e-09/; mv $W/m0 processor1/2e-09/.writeCommitted; one "(b) the two markers swapped"
again; mv processor0/2e-09/uniform $W/u0; mv processor1/2e-09/uniform processor0/2e-09/; mv $W/u0 processor1/2e-09/uniform; one "(c) the two uniform/ folders swapped"
cd $W; rm -rf pblast b0; bd; rs; rm -f .runLock; grep -n -i "time\b\|Time Value" solid/solid.xmf | head -4 | sed 's/^/   xmf: /'
/usr/bin/python3 - solid/solid.xmf <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read(); vals = re.findall(r'<Time Value="([^"]+)"', t)
print('   xmf times:', vals)
if len(vals) > 1:
    t = t.replace('<Time Value="%s"' % vals[1], '<Time Value="1.5e-09"', 1)
    g = list(re.finditer(r'<Grid Name="[^"]*" GridType="Uniform">.*?</Grid>', t, re.S))
    if len(g) > 2: t = t[:g[-1].start()] + t[g[-1].end():]
    open(p, 'w').write(t); print('   edited: a time changed, the last grid removed (grids %d)' % len(g))
P
rm -rf constant/solid; tryt 120 "(d1) solidToFoam with the edited solid.xmf" solidToFoam solid/solid.h5; echo "   said: $(msg 2 | cut -c1-200) | times with solid fields: $(ls -d [0-9]*/solid 2>/dev/null | tr '\n' ' ')"
tryt 300 "(d2) the restart to 3e-9 with the edited solid.xmf" cellBlastFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | said: $(msg 3 | cut -c1-250)"
echo "   xmf times now: $(grep -o '<Time Value="[^"]*"' solid/solid.xmf | tr '\n' ' ') | solid.h5 steps $(h5steps solid/solid.h5)"
