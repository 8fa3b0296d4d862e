#!/bin/bash
# CASETIMEOUT=900
# n04 (new, class 3/5: the post-processing a user runs on a running or cut case; docs: "ParaView opens solid.xmf",
# foamToVTK): the finished preview bd restarted to 3e-8 (writes every 1e-9) and while it runs: (a) `foamToVTK
# -latestTime` and `foamToVTK` (all times) twice (OpenFOAM's utility: the docs leave it to the user; does it read a time
# being written?), (b) a reader (h5py, as ParaView's XDMF reader) holding solid/solid.h5 open 15 s, and solid.xmf read
# 40 times: every step it lists must be in solid.h5 (the pair consistent at every read), (c) solidToFoam (ours: the
# lock). After the run: the solver's end (rc, End), solid.h5's steps against solid.xmf's. Then (d) a cut time made by
# hand (4e-08: a copy of the last time without .writeCommitted and without p): foamToVTK -latestTime (documented: not
# ours) and the restart (moves it aside). Never the solver disturbed, never a listed step missing from solid.h5.
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 3e-8 1e-9; rm -f .runLock; C=$PWD
(cellBlastFoam > log.bg 2>&1; echo "bg rc $?" >> log.bg) & bp=$!; sleep 5; echo "lock: $(head -c 120 .runLock | tr '\n' ' ')"
tryt 120 "(a1) foamToVTK -latestTime while the run goes" foamToVTK -latestTime; echo "   tail: $(tail -3 $W/try.log | tr '\n' ' ' | cut -c1-250) | VTK: $(ls VTK 2>/dev/null | head -3 | tr '\n' ' ')"
/usr/bin/python3 - solid/solid.h5 solid/solid.xmf > $W/rd.log 2>&1 <<'P' &
import h5py, re, sys, time, os
h5, xmf = sys.argv[1], sys.argv[2]
f = h5py.File(h5, 'r'); n0 = len(f['steps']) if 'steps' in f else -1; time.sleep(15); print('held solid.h5 open 15 s (%d steps at open)' % n0); f.close()
bad = 0; reads = 0
for i in range(40):
    try:
        x = open(xmf).read(); paths = set(re.findall(r'solid\.h5:(/[^<\s]+)', x))
        with h5py.File(h5, 'r') as g:
            miss = [p for p in paths if p not in g]
        reads += 1
        if miss: bad += 1; print('read %d: %d of %d listed datasets missing, e.g. %s' % (i, len(miss), len(paths), miss[0]))
    except Exception as e:
        bad += 1; print('read %d: %s: %s' % (i, type(e).__name__, str(e)[:150]))
    time.sleep(0.5)
print('xmf/h5 reads: %d, inconsistent or failed: %d' % (reads, bad))
P
rp=$!; sleep 3
tryt 120 "(a2) foamToVTK (every time) while the run goes" foamToVTK; echo "   tail: $(tail -2 $W/try.log | tr '\n' ' ' | cut -c1-250) | errors: $(grep -a -c -i 'error' $W/try.log)"
tryt 60 "(c) solidToFoam while the run goes" solidToFoam solid/solid.h5
wait $rp; echo "(b) reader: $(cat $W/rd.log | tr '\n' '|' | cut -c1-600)"
wait $bp; echo "solver: $(tail -1 log.bg) | End: $(grep -a -c '^End' log.bg) | $(grep -a -m1 -i 'fatal\|error\|unable' log.bg | cut -c1-200)"
echo "   solid.h5 steps $(h5steps solid/solid.h5) | solid.xmf steps $(grep -c '<Grid Name' solid/solid.xmf 2>/dev/null) | times: $(ls -d [0-9]* | tr '\n' ' ')"
cp -a 3e-08 4e-08; rm -f 4e-08/p 4e-08/.writeCommitted; sed -i 's/^ *value .*3e-08.*/    value 4e-08;/' 4e-08/uniform/time 2>/dev/null
tryt 120 "(d1) foamToVTK -latestTime on a cut 4e-08 (no marker, no p)" foamToVTK -latestTime; echo "   tail: $(grep -a -i 'time = \|warn\|error' $W/try.log | head -3 | tr '\n' ' ' | cut -c1-250) | VTK files of 4e-08: $(ls VTK 2>/dev/null | grep -c '4e-08\|_4[0-9]*\.')"
blastEnd 3.2e-8 1e-9; tryt 200 "(d2) the restart over the cut 4e-08" cellBlastFoam; echo "   $(grep -a -m1 'incomplete' $W/try.log | cut -c1-200) | times: $(ls -d [0-9]* .[0-9]* [0-9]*.incomplete* 2>/dev/null | tr '\n' ' ')"
