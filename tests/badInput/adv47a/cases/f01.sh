#!/bin/bash
# f01 (class 5, adv46a e01 varied: the commit marker of the restart time cut at other places, 64 bytes of 2e-09/rho zeroed):
# the finished preview, startFrom latestTime, endTime 3e-9; 2e-09/.writeCommitted cut to N bytes for N at: the time line
# only, inside "digest", inside " ended", right after the digest line, inside rho's file line, right after rho's line,
# inside the seal line, right after the seal line (no "end"), inside "end"; then (k) 64 bytes of the marker zeroed inside its
# file lines, (l) the seal line zeroed (the rest intact), (m) the seal line and rho's file line removed (an edited marker,
# "an earlier build's" unsealed record without rho). Each: cellBlastFoam must move 2e-09 aside (continue from 1e-09) or
# refuse naming it; never read the damaged rho (a crash, or a run from it). The run is cut at 45 s: only where it
# restarted from matters (its "Restarting from" line), the restart runs on.
. "$(dirname "$0")/../lib.sh"
bd; rs; rm -f .runLock; cp -a . ../keep; M=2e-09/.writeCommitted
dmg() { /usr/bin/python3 - <<'P'
s=bytearray(open('2e-09/rho','rb').read()); k=s.find(b'internalField'); k=s.find(b'(', k)+200; s[k:k+64]=b'\0'*64; open('2e-09/rho','wb').write(s)
P
}
pos() { /usr/bin/python3 - "$1" <<'P'
import sys; t=open('2e-09/.writeCommitted','rb').read(); w=sys.argv[1]
r=t.find(b' rho\n')+5; s=t.find(b'\nseal ')+1; e=t.find(b'\n',s)+1
print({'time':t.find(b'\n')+1,'digest':t.find(b'digest')+4,'ended':t.find(b' ended')+3,'afterDigest':t.find(b'\n',t.find(b'digest'))+1,
 'inRho':r-20,'afterRho':r,'inSeal':s+10,'afterSeal':e,'inEnd':e+2}[w])
P
}
one() { local l=$1; echo "   marker now ($(stat -c %s $M) bytes): $(tail -c 60 $M | tr '\n' '|' | tr '\0' '@')"; dmg; tryt 45 "$l" cellBlastFoam
  echo "   $(grep -a -m1 'Restarting from\|moved aside\|Moving\|incomplete' $W/try.log | cut -c1-200) | sigFpe: $(grep -ac 'sigFpe\|Floating point' $W/try.log) | times now: $(ls -d [0-9]* *incomplete* 2>/dev/null | tr '\n' ' ')"
  cd $W; rm -rf blast; cp -a keep blast; cd blast; }
for w in time digest ended afterDigest inRho afterRho inSeal afterSeal inEnd; do n=$(pos $w); head -c $n $M > m; mv m $M; one "cut at $w ($n bytes)"; done
/usr/bin/python3 -c "
t=bytearray(open('$M','rb').read()); k=t.find(b'file ')+100; t[k:k+64]=b'\0'*64; open('$M','wb').write(t)"; one "(k) 64 bytes zeroed in the file lines"
/usr/bin/python3 -c "
t=bytearray(open('$M','rb').read()); s=t.find(b'\nseal ')+1; e=t.find(b'\n',s); t[s:e]=b'\0'*(e-s); open('$M','wb').write(t)"; one "(l) the seal line zeroed"
grep -v '^seal \| rho$' $M > m; mv m $M; one "(m) the seal line and rho's line removed"
