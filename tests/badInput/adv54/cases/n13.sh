#!/bin/bash
# CASETIMEOUT=900
# n13 (new, class 1/5: the water probes switched off for one restart and on again - a user saving time - so that the
# probe log has a gap): bd (finished at 2e-9) restarted to 4e-9 with the fluidProbes function object removed from
# system/controlDict (its `enabled false;`), then to 8e-9 with it back: planeWave -check, incidentWindow.py and
# plotBlast.py on the case; against p8 (the same run to 8e-9 without the gap). Expected: the gap (2-4 ns: no rows) named
# by the measures or refused ("the probe log does not cover 2e-09 to 4e-09"); measures over a log with a hole that differ
# from p8's without a word = SILENT.
. "$(dirname "$0")/../lib.sh"
p8; R=$PWD; cd $W; bd; latest; blastEnd 4e-9 1e-9; rm -f .runLock
/usr/bin/python3 - system/controlDict <<'P'
import sys, re
p = sys.argv[1]; t = open(p).read(); t2 = re.sub(r'(fluidProbes\s*\{)', r'\1\n        enabled false;', t, count=1); open(p, "w").write(t2); print("   fluidProbes disabled:", t2 != t)
P
tryt 300 "to 4e-9 without the probes" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-200)"
sed -i '/^ *enabled false;$/d' system/controlDict; blastEnd 8e-9 1e-9; rm -f .runLock; tryt 600 "to 8e-9 with the probes again" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-200) | probe logs: $(ls postProcessing/fluidProbes | tr '\n' ' ') rows $(cat postProcessing/fluidProbes/*/p | grep -vc '^#')"
tryt 300 "planeWave -check (the gap)" planeWave -case .; grep -a -A2 '^# probe' $W/try.log | sed -n 2,3p | cut -c1-220; grep -a -i 'gap\|cover\|missing\|hole' $W/try.log | head -2
echo "   p8 (no gap): $(grep -a -A2 '^# probe' $R/log.planeWave | sed -n 2,3p | cut -c1-220 | tr '\n' '|')"
iw .; echo "   incidentWindow: $(grep -a -v '^ *$' $W/try.log | tail -n 2 | tr '\n' '|' | cut -c1-300)"
