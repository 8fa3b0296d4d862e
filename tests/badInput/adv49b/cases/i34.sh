#!/bin/bash
# i34 (class 6, loading tables whose step count is huge): the smoke indentation with (a) a last hold of 1e9 s (maxDeltaT 5:
# 2e8 steps), (b) holdGrowth 1 with holdDeltaT0 1e-9 (a 15 s hold: 1.5e10 steps), (c) maxDepthIncrement 1e-15 (a 1.41 um
# load: 1.4e9 steps), (d) maxDeltaT 1e-300 with the smoke table, (e) holdGrowth 1e300, (f) maxDeltaT below holdDeltaT0
# (0.001 < 0.01: valid alone), (g) forceTarget 1e-3 N (a force the first row never reaches): each refused within 60 s naming
# the estimate and maxSteps (or the entries that do not fit together), or run with a count it can do; nothing written by a
# refusal; no hang.
. "$(dirname "$0")/../lib.sh"
ind; cp constant/indenterProperties ../i0
for e in "HOLD" "holdGrowth 1|holdDeltaT0 1e-9" "maxDepthIncrement 1e-15" "maxDeltaT 1e-300" "holdGrowth 1e300" "maxDeltaT 0.001" "forceTarget 1e-3"; do
  cp ../i0 constant/indenterProperties; if [ "$e" = HOLD ]; then /usr/bin/python3 - <<'P'
import re; p = 'constant/indenterProperties'; t = open(p).read(); i = t.rindex('hold'); j = t.index(')', i)
t = t[:i] + re.sub(r'[0-9.eE+-]+\s*$', '1e9', t[i:j]) + t[j:]; open(p, 'w').write(t); print("   last hold row now: " + t[i-12:j+1].replace('\n', ' '))
P
  else IFS='|' read -ra kv <<< "$e"; for x in "${kv[@]}"; do set -- $x; sete constant/indenterProperties $1 $2 2>/dev/null || echo "$1 $2;" >> constant/indenterProperties; done; fi
  tryt 90 "[$e]" cellIndentationFoam; echo "   written: $(ls postProcessing/indentation 2>/dev/null | tr '\n' ' ') | force rows $(nLines postProcessing/indentation/force.dat)"; rm -rf postProcessing; done
