#!/bin/bash
# x76: a power loss cutting the latest time's .writeCommitted in the middle of a line (half its bytes kept), with 64 bytes of 2e-09/p zeroed: the restart refuses (damaged marker) or continues from the damaged field?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; n=$(stat -c %s 2e-09/.writeCommitted); head -c $((n/2)) 2e-09/.writeCommitted > ../m; cp ../m 2e-09/.writeCommitted; tail -c 120 2e-09/.writeCommitted; echo
/usr/bin/python3 - <<'P'
s=bytearray(open('2e-09/p','rb').read()); k=s.find(b'internalField'); k=s.find(b'(', k)+200; s[k:k+64]=b'\0'*64; open('2e-09/p','wb').write(s)
P
try "marker cut in half, p damaged" cellBlastFoam; grep -a -i "marker\|commit\|damag" $W/try.log | head -3 | cut -c1-250
