#!/bin/bash
# CASETIMEOUT=900
# l03 (new, class 1: the indentation's protocol row in progress at the kill, changed for the restart - the checkpoint
# records the rows "already run"; is the row running at the kill one of them?): the killed indentation ik (killed 1 s
# after its first checkpoint, 10x finer depth steps) restarted after (a) the row in progress at the checkpoint (the
# last row of force.dat's stage) changed (its target depth or time x1.2), (b) a row after it changed (allowed: not yet
# run), (c) maxDepthIncrement changed back to 0.1e-6 (the step of the rows already run). Expected: (a) refused naming the
# row (part of it ran with the old target) or said; (b) runs; (c) refused or said; a restart that continues the row with
# a changed target without a word = SILENT.
. "$(dirname "$0")/../lib.sh"
ik; I=postProcessing/indentation; echo "   force.dat stages so far: $(grep -v '^#' $I/force.dat | awk '{print $NF}' | uniq -c | tr -s ' ' | tr '\n' ' ')"
sed -n '/protocol/,/);/p' constant/indenterProperties | head -14 | sed 's/^/   /'; cd $W; cp -a ind i0; back() { cd $W; rm -rf ind; cp -a i0 ind; cd ind; }
rowEdit() { /usr/bin/python3 - constant/indenterProperties "$1" <<'P'
import re, sys
p, k = sys.argv[1], int(sys.argv[2]); t = open(p).read(); i = t.index('protocol'); j = t.index(');', i)
body = t[i:j]; rows = list(re.finditer(r'\(([^()]*)\)', body))
r = rows[k]; nums = r.group(1).split(); out = []
done = False
for x in nums:
    try: v = float(x); out.append(repr(v * 1.2) if not done and v != 0 else x); done = done or v != 0
    except ValueError: out.append(x)
new = body[:r.start(1)] + ' '.join(out) + body[r.end(1):]; open(p, 'w').write(t[:i] + new + t[j:]); print('   protocol row %d: (%s) -> (%s)' % (k, r.group(1).strip(), ' '.join(out)))
P
}
last=$(grep -v '^#' $W/i0/$I/force.dat | tail -1 | awk '{print $NF}'); echo "   stage at the kill: $last"
one() { tryt 600 "$1" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-350)"; grep -a -m2 -i 'changed\|row' $W/try.log | cut -c1-200 | sed 's/^/   log: /'; }
back; k=$(case $last in A) echo 0;; B) echo 1;; C) echo 2;; *) echo 0;; esac); rowEdit $k; one "(a) the row in progress ($last, row index $k) changed x1.2"
back; rowEdit $((k+1)); one "(b) the next row (index $((k+1))) changed x1.2"
back; sed -i 's/maxDepthIncrement 0.01e-6/maxDepthIncrement 0.1e-6/' constant/indenterProperties; grep -c 'maxDepthIncrement 0.1e-6' constant/indenterProperties | sed 's/^/   maxDepthIncrement back to 0.1e-6: /'; one "(c) maxDepthIncrement 0.01e-6 -> 0.1e-6"
