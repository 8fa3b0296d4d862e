#!/bin/bash
# CASETIMEOUT=900
# (corrected after its first run: the record's digests have 40 hex digits, not 16; (a) had changed nothing)
# h06 (class 5+1, adv47a f04 (e) varied: the restart time's uniform/inputDigests and state records altered, nothing else;
# the finished preview, startFrom latestTime, endTime 3e-9): (a) one hex digit of a digest changed, (b) a line appended,
# (c) cut in the middle of a line, (d) replaced by bd2's (another run's record, pulse doubled), (e) a comment line
# prepended, (f) uniform/fsiState emptied, (g) uniform/solidState emptied, (h) functionObjectProperties emptied.
# Each refused naming the damaged record (not an input as changed), or (h) a restart equal to the clean one; never a
# restart with a record the marker does not vouch for.
. "$(dirname "$0")/../lib.sh"
bd2; cp 2e-09/uniform/inputDigests $W/bd2digests; cd $W; rm -rf blast2
bd; rs; rm -f .runLock; cp -a . ../keep; D=2e-09/uniform/inputDigests; echo "record: $(wc -lc < $D) (lines, bytes); bd2's differs: $(cmp -s $D $W/bd2digests && echo no || echo yes)"
one() { tryt 90 "$1" cellBlastFoam; echo "   $(grep -a -m1 'Restarting from' $W/try.log | cut -c1-90) | sig lines: $(sig) | times: $(ls -d [0-9]* *incomplete* 2>/dev/null | tr '\n' ' ')"; cd $W; rm -rf blast; cp -a keep blast; cd blast; }
/usr/bin/python3 -c "
import re; f='$D'; s=open(f).read(); m=list(re.finditer(r'\b[0-9a-f]{40}\b', s)); k=m[len(m)//2].start()+3; c=s[k]; n='0' if c!='0' else '1'; open(f,'w').write(s[:k]+n+s[k+1:]); print('   a hex digit', c, '->', n, 'of', len(m), 'digests')"; one "(a) one hex digit changed"
echo "mieGruneisenCoeffs/Gamma0 0123456789abcdef" >> $D; one "(b) a line appended"
/usr/bin/python3 -c "
f='$D'; s=open(f).read(); k=s.find('\n', len(s)//2); open(f,'w').write(s[:k-5]); print('   cut at', k-5, 'of', len(s))"; one "(c) cut inside a line"
cp $W/bd2digests $D; one "(d) bd2's record"
sed -i '1i // edited by hand' $D; one "(e) a comment line prepended"
: > 2e-09/uniform/fsiState; one "(f) fsiState emptied"
: > 2e-09/uniform/solidState; one "(g) solidState emptied"
: > 2e-09/uniform/functionObjects/functionObjectProperties; one "(h) functionObjectProperties emptied"
