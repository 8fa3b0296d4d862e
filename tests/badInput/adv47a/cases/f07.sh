#!/bin/bash
# f07 (class 5, f01 (k)-(m) reduced: the commit marker of 2e-09 intact, only 64 bytes of 2e-09/rho zeroed; the finished
# preview, startFrom latestTime, endTime 3e-9): (a) rho damaged, (b) rhoE damaged, (c) rhoU damaged, (d) p damaged (the
# restart does not read it; adv46b d45's kind). Each refused naming the file (its digest differs from the marker's), or
# the time moved aside; never a crash (sigFpe) while reading the damaged field nor a run from it. Cut at 45 s each.
. "$(dirname "$0")/../lib.sh"
bd; rs; rm -f .runLock; cp -a . ../keep
dmg() { /usr/bin/python3 - "$1" <<'P'
import sys; f='2e-09/'+sys.argv[1]; s=bytearray(open(f,'rb').read()); k=s.find(b'internalField'); k=s.find(b'(', k)+200; s[k:k+64]=b'\0'*64; open(f,'wb').write(s)
P
}
for f in rho rhoE rhoU p; do dmg $f; tryt 45 "64 bytes of 2e-09/$f zeroed, marker intact" cellBlastFoam
  echo "   $(grep -a -m1 'Restarting from' $W/try.log | cut -c1-120) | crashed: $(grep -ac 'sigHandler' $W/try.log) | digest named: $(grep -ac 'digest' $W/try.log) | times: $(ls -d [0-9]* 2>/dev/null | tr '\n' ' ')"
  cd $W; rm -rf blast; cp -a keep blast; cd blast; done
