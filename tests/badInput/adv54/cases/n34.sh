#!/bin/bash
# CASETIMEOUT=900
# n34 (new, class 2/5: planeWave interrupted while it WRITES reference.dat - n17 killed it before; its writer opens the
# file in place, then writes the sidecar): p8; planeWave -case . -dz 12.5e-9 in the background, reference.dat's size and
# time polled every 5 ms, the run SIGKILLed as soon as the file changes (three tries); then the files' state, ok_ (the
# package's check), incidentWindow.py and planeWave -check -reference on it. Expected: the earlier reference whole (the
# new one written aside and renamed) or the new one whole with its sidecar; a cut reference with the old sidecar refused
# as "edited or damaged after it was written" = UNCLEAR (a kill, not an edit; the earlier result lost = DATALOSS).
. "$(dirname "$0")/../lib.sh"
p8; cp -a . $W/p0; r=postProcessing/planeWave/0/reference.dat; md5sum $r $r.fnv1a64 > $W/m0
for k in 1 2 3; do cd $W; rm -rf p8; cp -a p0 p8; cd p8; s0=$(stat -c '%Y.%s' $r); planeWave -case . -dz 12.5e-9 > log.pw 2>&1 & p=$!
  i=0; while [ "$(stat -c '%Y.%s' $r 2>/dev/null)" = "$s0" ] && kill -0 $p 2>/dev/null && [ $i -lt 40000 ]; do sleep 0.005; i=$((i+1)); done; kill -KILL $p 2>/dev/null; wait $p 2>/dev/null
  echo "   try $k: killed after $i polls | reference.dat $(stat -c %s $r) B, $(md5sum -c $W/m0 2>/dev/null | sed 's/.*planeWave\/0\///' | tr '\n' ' ') | last line: $(tail -c 60 $r | tr '\n' '|')"; ok_ $r
  iw .; echo "   incidentWindow: $(grep -a -v '^ *$' $W/try.log | tail -n 1 | cut -c1-250)"; done
