#!/bin/bash
# CASETIMEOUT=600
# n35 (new, class 4/1: OpenFOAM's #includeFunc - a documented way to add a function object - in controlDict's functions{}):
# (a) the short preview with `#includeFunc minMaxMagnitude` inside functions{}: a fresh run; (b) bd (finished at 2e-9)
# restarted to 3e-9 with it added (a function object added at a restart); (c) then restarted to 4e-9 with it removed
# again; planeWave -case . after each. Expected: (a) runs (the function object's log written) or refused naming the line;
# (b), (c) a decision named (continued: its log starts at 2e-9; or refused as a changed function object list); a crash
# of the keyword check or a measure of another run's log = as it falls.
. "$(dirname "$0")/../lib.sh"
addF() { /usr/bin/python3 - system/controlDict <<'P'
import sys, re
p = sys.argv[1]; t = open(p).read(); m = re.search(r"\nfunctions\s*\{\s*\n", t); t = t[:m.end()] + "    #includeFunc minMaxMagnitude\n" + t[m.end():]; open(p, "w").write(t)
P
grep -n -A2 '^functions' system/controlDict | head -3 | tr '\n' ' '; echo; }
sb; addF; tryt 200 "(a) a fresh short run with #includeFunc minMaxMagnitude" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250) | postProcessing: $(ls postProcessing | tr '\n' ' ')"
cd $W; rm -rf blast; bd; addF; rs; rm -f .runLock; tryt 300 "(b) bd restarted to 3e-9 with it added" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300) | postProcessing: $(ls postProcessing | tr '\n' ' ')"
sed -i '/#includeFunc minMaxMagnitude/d' system/controlDict; blastEnd 4e-9 1e-9; rm -f .runLock; tryt 300 "(c) restarted to 4e-9 with it removed" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300)"
tryt 300 "planeWave -case . after" planeWave -case .; echo "   said: $(say 2 | cut -c1-250)"
