#!/bin/bash
# v60: probes at restart: the fluidProbes function object removed
. "$(dirname "$0")/../lib.sh"
blastDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9; /usr/bin/python3 - <<'P'
s=open('system/controlDict').read(); i=s.index('functions'); j=s.index('{',i); k=s.rindex('}'); s=s[:j]+'{\n}\n'+s[k+1:]; open('system/controlDict','w').write(s)
P
grep -n -A2 functions system/controlDict; cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A4 FATAL log.r | head -6 | cut -c1-300
