#!/bin/bash
# w77: indenterProperties at the edges: radius 22.5 (um as m), radius 0, tolerance 0, penaltyFactor nan, holdGrowth 0.5, holdDeltaT0 0, maxDepthIncrement 1e300, an empty protocol ()
. "$(dirname "$0")/../lib.sh"
ind; each constant/indenterProperties "radius 22.5" "radius 0" "tolerance 0" "penaltyFactor nan" "holdGrowth 0.5" "holdDeltaT0 0" "maxDepthIncrement 1e300" -- cellIndentationFoam
/usr/bin/python3 - <<'P'
import re; s=open('constant/indenterProperties').read(); s=re.sub(r'\nprotocol\s*\(.*?\n\);', '\nprotocol ();', s, count=1, flags=re.S); open('constant/indenterProperties','w').write(s)
P
try "protocol ()" cellIndentationFoam
