#!/bin/bash
# CASETIMEOUT=900
# n17 (new, class 2/5: planeWave interrupted - a user's Ctrl-C or a killed terminal - over an earlier reference): p8 (its
# reference.dat, sidecar, measures.dat, solidMeasures.dat from planeWave); planeWave -case . -dz 12.5e-9 (a finer column:
# longer, a new reference) SIGKILLed at 1, 3, 6 s (three copies), then: the files' state (size, md5 vs before),
# incidentWindow.py and planeWave -check -reference <the case's reference.dat> on what is left. Expected: the earlier
# files whole (kept) or the new ones whole; never a reference.dat and sidecar of two runs taken as one, nor refused as
# "edited by hand" (it is a kill: UNCLEAR); measures.dat of the new run beside the old reference without a word = SILENT.
. "$(dirname "$0")/../lib.sh"
p8; cp -a . $W/p0; md5sum postProcessing/planeWave/0/* > $W/m0
for s in 1 3 6; do cd $W; rm -rf p8; cp -a p0 p8; cd p8; planeWave -case . -dz 12.5e-9 > log.pw 2>&1 & p=$!; sleep $s; kill -KILL $p 2>/dev/null; wait $p 2>/dev/null
  echo "   killed at $s s: $(md5sum -c $W/m0 2>/dev/null | sed 's/.*planeWave\/0\///' | tr '\n' ' ') | files: $(ls postProcessing/planeWave/0 | tr '\n' ' ')"
  iw .; echo "   incidentWindow: $(grep -a -v '^ *$' $W/try.log | tail -n 1 | cut -c1-250)"
  tryt 300 "   planeWave -check -reference (the case's)" planeWave -case . -check -reference postProcessing/planeWave/0/reference.dat; echo "   said: $(say 1 | cut -c1-250)"; done
