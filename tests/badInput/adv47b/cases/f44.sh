#!/bin/bash
# (corrected after its first run: my foamDictionary call printed the whole file instead of endTime)
# f44 (class 4/6, maxWrites at its bound): sod with writeInterval endTime/3 and maxWrites 3 (3 writes exactly, endTime/3 not exact in binary): accepted, times E/3, 2E/3, E written; endTime/10 with maxWrites 10: accepted; endTime/10 with maxWrites 9: refused naming maxWrites and the count 10.
. "$(dirname "$0")/../lib.sh"
sod; cp system/controlDict ../cd0; E=$(foamDictionary -expand system/controlDict 2>/dev/null | awk '/^endTime/{gsub(";", "", $2); print $2; exit}'); echo "   endTime $E"
for n in "3 3" "10 10" "10 9"; do set -- $n; cp ../cd0 system/controlDict; wi=$(/usr/bin/python3 -c "print(repr(float('$E') / $1))"); sete system/controlDict writeInterval $wi; echo "maxWrites $2;" >> system/controlDict
  tryt 120 "writeInterval E/$1 = $wi, maxWrites $2" rhoRiemannFoam; echo "   times: $(ls -d [0-9]* | tr '\n' ' ')"; rm -rf [1-9]* 0.[0-9]* postProcessing; done
