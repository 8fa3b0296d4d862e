#!/bin/bash
# y16: a .writeCommitted cut after its first file lines (digest, T, U listed; p and the rest missing: the marker's tail did not reach the disk) and 64 bytes of 2e-09/p zeroed; restart from latestTime: refused/moved aside, or continued from the damaged p? (control: the whole marker with the same damage)
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cp -r . ../keep
dmg() { /usr/bin/python3 - <<'P'
s=bytearray(open('2e-09/p','rb').read()); k=s.find(b'internalField'); k=s.find(b'(', k)+200; s[k:k+64]=b'\0'*64; open('2e-09/p','wb').write(s)
P
}
dmg; try "control: whole marker, p damaged" cellBlastFoam
rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast; head -3 2e-09/.writeCommitted > m; grep -c . m; mv m 2e-09/.writeCommitted; dmg; try "marker cut after its T line, p damaged" cellBlastFoam; ls -da [1-9]* 2>/dev/null | tr '\n' ' '; echo
rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast; head -c 20 2e-09/.writeCommitted > m; mv m 2e-09/.writeCommitted; dmg; try "marker cut to its digest line, p damaged" cellBlastFoam; ls -da [1-9]* 2>/dev/null | tr '\n' ' '; echo
