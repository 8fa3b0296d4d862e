#!/bin/bash
# g02 (class 1, uniform/time) A = bd with 2e-09/uniform/time's deltaT and deltaT0 divided by 1000 (valid numbers), restart latestTime to 3e-9; B = the clean restart. The user guide says uniform/time holds the exact deltaT a restart needs: a changed one is refused naming 2e-09/uniform/time, or A continues as B; never a silently other time line.
. "$(dirname "$0")/../lib.sh"
bd; mv $W/blast $W/B; cd $W/B; rs; tryt 240 "B clean restart" cellBlastFoam
bd; rs; /usr/bin/python3 - 2e-09/uniform/time <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read()
n = re.sub(r'^(deltaT0?\s+)([-+0-9.eE]+);', lambda m: m.group(1) + repr(float(m.group(2)) / 1000) + ';', t, flags=re.M)
print("   deltaT lines:", [l for l in n.splitlines() if l.startswith('deltaT')]); open(p, 'w').write(n)
P
sums > ../s0
tryt 240 "A: uniform/time deltaT/1000" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after; ls -d 3e-09 >/dev/null 2>&1 && cmpRef $W/B
