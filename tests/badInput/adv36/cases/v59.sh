#!/bin/bash
# v59: probes at restart: a new function object added (a second probes object)
. "$(dirname "$0")/../lib.sh"
blastDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9; /usr/bin/python3 - <<'P'
s=open('system/controlDict').read(); i=s.index('functions'); j=s.index('{',i)+1; s=s[:j]+'\n    extraProbes { type movingMeshProbes; libs ("libfsi.so"); fields (p); probeLocations ((1e-7 15e-6 0)); }'+s[j:]; open('system/controlDict','w').write(s)
P
cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A4 FATAL log.r | head -6 | cut -c1-300; ls postProcessing
