#!/bin/bash
# y20: y16 on 2 ranks: processor0/2e-09/.writeCommitted cut after its third line and 64 bytes of processor0/2e-09/p zeroed; 2-rank restart from latestTime: refused/moved aside, or continued from the damaged rank?
. "$(dirname "$0")/../lib.sh"
pblastDone; latest; blastEnd 3e-9 1e-9; head -3 processor0/2e-09/.writeCommitted > m; mv m processor0/2e-09/.writeCommitted
/usr/bin/python3 - <<'P'
s=bytearray(open('processor0/2e-09/p','rb').read()); k=s.find(b'internalField'); k=s.find(b'(', k)+200; s[k:k+64]=b'\0'*64; open('processor0/2e-09/p','wb').write(s)
P
run 150 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1; tail -1 log.r | cut -c1-150; fatal log.r 4; echo "processor0: $(ls -a processor0 | tr '\n' ' ')"
