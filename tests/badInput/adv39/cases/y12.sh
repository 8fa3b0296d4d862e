#!/bin/bash
# y12: .writeCommitted half-written: (a) the latest's marker cut in the middle of its first digest line; (b) every time's marker empty (1e-09 and 2e-09); (c) 2e-09's marker empty and startFrom startTime 2e-09: refused, then -acceptEdited; each: refused naming it, moved aside, or continued?; (d) cut marker and 64 zero bytes in 2e-09/p; (e) (c) with -overwrite
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cp -r . ../keep; echo "marker: $(head -c 120 2e-09/.writeCommitted | tr '\n' '|')"
head -c 20 2e-09/.writeCommitted > m; mv m 2e-09/.writeCommitted; try "(a) cut marker" cellBlastFoam; ls -da [1-9]* .*[0-9]* 2>/dev/null | tr '\n' ' '; echo
rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast; : > 1e-09/.writeCommitted; : > 2e-09/.writeCommitted; try "(b) both markers empty" cellBlastFoam; ls -da [0-9]* .*[0-9]* 2>/dev/null | tr '\n' ' '; echo; grep -a -m2 -i "aside\|start" $W/try.log | cut -c1-200
rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast; : > 2e-09/.writeCommitted; sed -i 's/^startFrom .*/startFrom startTime;/; s/^startTime .*/startTime 2e-09;/' system/controlDict; try "(c) startTime 2e-09, empty marker" cellBlastFoam; try "(c) -acceptEdited" cellBlastFoam -acceptEdited
rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast; head -c 20 2e-09/.writeCommitted > m; mv m 2e-09/.writeCommitted; /usr/bin/python3 - <<'P'
s=bytearray(open('2e-09/p','rb').read()); k=s.find(b'internalField'); k=s.find(b'(', k)+200; s[k:k+64]=b'\0'*64; open('2e-09/p','wb').write(s)
P
try "(d) cut marker (digest line, no file lines) and 64 zero bytes in 2e-09/p" cellBlastFoam; ls -da [1-9]* .*[0-9]* 2>/dev/null | tr '\n' ' '; echo
rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast; : > 2e-09/.writeCommitted; sed -i 's/^startFrom .*/startFrom startTime;/; s/^startTime .*/startTime 2e-09;/' system/controlDict; try "(e) startTime 2e-09, empty marker, -overwrite" cellBlastFoam -overwrite; ls -da [1-9]* 2>/dev/null | tr '\n' ' '; echo
