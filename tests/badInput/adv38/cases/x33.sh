#!/bin/bash
# x33: power loss after a commit (ext4 delayed allocation): the latest time's .writeCommitted left as a ZERO-BYTE file; restart: refused naming it / moved aside / continued from it? and a field file of that time zero bytes with its marker whole?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cp -r . ../keep; : > 2e-09/.writeCommitted
try "empty marker" cellBlastFoam; ls -a 2e-09* -d | tr '\n' ' '; echo; rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast
: > 2e-09/U; try "empty 2e-09/U" cellBlastFoam; ls -d 2e-09* | tr '\n' ' '; echo
rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast; : > 2e-09/.writeCommitted; /usr/bin/python3 - <<'P'
s=bytearray(open('2e-09/p','rb').read()); k=s.find(b'internalField'); k=s.find(b'(', k)+200; s[k:k+64]=b'\0'*64; open('2e-09/p','wb').write(s)
P
try "empty marker and 64 zero bytes in 2e-09/p" cellBlastFoam; ls -d 2e-09* | tr '\n' ' '; echo
