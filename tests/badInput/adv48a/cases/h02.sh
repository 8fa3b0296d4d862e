#!/bin/bash
# CASETIMEOUT=900
# h02 (class 5, adv47a f07 varied: the files of the restart time that fix19d's early check leaves out (p, U, T) and the
# mesh/state files; the finished preview, startFrom latestTime, endTime 3e-9, the marker intact): (a) p[5] 1.23e5 (internal
# value), (b) the pulse table of 2e-09/p's top patch: its second row's pressure doubled (text), (c) U 64 B zeroed, (d) T 64 B
# zeroed, (e) 2e-09/polyMesh/points 64 B zeroed, (f) meshPhi 64 B zeroed, (g) uniform/solidState 64 B zeroed in its middle,
# (h) uniform/fsiState one digit changed, (i) uniform/time emptied. Each refused naming the file, or (p, U, T, if the
# restart does not use them) a run whose 3e-09 equals the clean restart's (r: reference). Never a sigFpe, never a run
# from changed state with other results.
. "$(dirname "$0")/../lib.sh"
bd; rs; rm -f .runLock; cp -a . ../keep
tryt 120 "(r) clean restart (reference)" cellBlastFoam; cp -a 3e-09 ../ref3 2>/dev/null; ls ../ref3 | tr '\n' ' '; echo; cd $W; rm -rf blast; cp -a keep blast; cd blast
one() { local l=$1; shift; tryt 90 "$l" cellBlastFoam "$@"; echo "   $(grep -a -m1 'Restarting from' $W/try.log | cut -c1-90) | sig lines: $(sig) | times: $(ls -d [0-9]* *incomplete* 2>/dev/null | tr '\n' ' ')"
  [ -d 3e-09 ] && echo "   3e-09 vs reference: $(for f in rho rhoE rhoU p U; do cmp -s 3e-09/$f ../ref3/$f && echo "$f same" || echo "$f DIFFERS"; done | tr '\n' ' ')"; cd $W; rm -rf blast; cp -a keep blast; cd blast; }
setb 2e-09/p 5 1.23e5; one "(a) p[5] 1.23e5"
/usr/bin/python3 - 2e-09/p <<'P'
import re, sys; f = sys.argv[1]; s = open(f, 'rb').read(); k = s.find(b'table', s.find(b'top')); m = list(re.finditer(rb'\(\s*([-+0-9.eE]+)\s+([-+0-9.eE]+)\s*\)', s[k:k+4000]))[1]
a, b = k + m.start(2), k + m.end(2); v = float(s[a:b]); print('   2e-09/p pulse row 2: %s -> %r' % (s[a:b].decode(), 2 * v)); open(f, 'wb').write(s[:a] + repr(2 * v).encode() + s[b:])
P
one "(b) 2e-09/p pulse row 2 doubled"
dmgf 2e-09/U; one "(c) U 64 B zeroed"
dmgf 2e-09/T; one "(d) T 64 B zeroed"
/usr/bin/python3 -c "
import sys; f='2e-09/polyMesh/points'; s=bytearray(open(f,'rb').read()); k=s.find(b'(', s.find(b'FoamFile')+400)+200; s[k:k+64]=b'\0'*64; open(f,'wb').write(s)"; one "(e) polyMesh/points 64 B zeroed"
/usr/bin/python3 -c "
import sys; f='2e-09/meshPhi'; s=bytearray(open(f,'rb').read()); k=s.find(b'(', s.find(b'internalField'))+200; s[k:k+64]=b'\0'*64; open(f,'wb').write(s)"; one "(f) meshPhi 64 B zeroed"
s=$(stat -c %s 2e-09/uniform/solidState); dd if=/dev/zero of=2e-09/uniform/solidState bs=1 seek=$((s/2)) count=64 conv=notrunc 2>/dev/null; one "(g) solidState 64 B zeroed"
/usr/bin/python3 -c "
import re; f='2e-09/uniform/fsiState'; s=open(f).read(); m=list(re.finditer(r'[0-9]', s[s.find('}')+1:]))[-5]; k=s.find('}')+1+m.start(); d=s[k]; s=s[:k]+str((int(d)+1)%10)+s[k+1:]; open(f,'w').write(s); print('   fsiState: a digit', d, '->', (int(d)+1)%10)"; one "(h) fsiState one digit changed"
: > 2e-09/uniform/time; one "(i) uniform/time emptied"
