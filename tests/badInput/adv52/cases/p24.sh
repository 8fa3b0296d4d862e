#!/bin/bash
# CASETIMEOUT=600
# p24 (new, class 5: riemannError, the verification's measure, on a damaged time): the sod tube run to its end (sodDone);
# its end time's p with (a) one cell's value x1.5 as ascii text (parse-valid), (b) 64 zeroed bytes in the middle of the
# list, (c) the time's .writeCommitted removed (a time of another tool). riemannError then compares with the exact
# solution. Expected: (a), (b) refused naming the file (its bytes are not its commit's: the digest), never an L1 error
# printed from the damaged field; (c) judged as a time without our commit (said).
. "$(dirname "$0")/../lib.sh"
sodDone; T=$(ls -d [0-9]* | grep -v '^0$' | sort -g | tail -1); echo "   end time $T"; cp -a . $W/s0; again() { cd $W; rm -rf sod; cp -a s0 sod; cd sod; }
tryt 120 "(0) riemannError (control)" riemannError; grep -a -i "L1\|error" $W/try.log | head -3 | cut -c1-160 | sed 's/^/   /'
/usr/bin/python3 - $T/p <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read(); m = re.search(r'internalField\s+nonuniform\s+List<scalar>\s*\d+\s*\(\s*', t); s = m.end()
e = t.index('\n', s + 200); line = t[t.rindex('\n', 0, e - 1) + 1:e]; v = float(line); t = t[:e - len(line)] + repr(v * 1.5) + t[e:]
open(p, 'w').write(t); print('   %s: a value %s -> %s' % (p, line.strip(), repr(v * 1.5)))
P
tryt 120 "(a) riemannError with one p value x1.5" riemannError; echo "   said: $(msg 3 | cut -c1-250)"; grep -a -i "L1" $W/try.log | head -2 | cut -c1-160 | sed 's/^/   /'; again
/usr/bin/python3 -c "
import sys; p = sys.argv[1]; b = bytearray(open(p, 'rb').read()); i = b.index(b'(') + 300; b[i:i+64] = b'\0' * 64; open(p, 'wb').write(b)" $T/p
tryt 120 "(b) riemannError with 64 zeroed bytes in p" riemannError; echo "   sig: $(sig) | said: $(msg 3 | cut -c1-250)"; again
rm $T/.writeCommitted; tryt 120 "(c) riemannError with the time's .writeCommitted removed" riemannError; echo "   said: $(msg 3 | cut -c1-250) | notes: $(grep -a -m1 -i 'commit\|marker' $W/try.log | cut -c1-200)"
