#!/bin/bash
# CASETIMEOUT=900
# p23 (new, class 5/1: parse-valid edits of the indentation's own text results before a restart; force.dat and peaks.dat
# carry the run's identity, but their rows?): the killed indentation ik: (a) force.dat's last row's force x1.5, (b) a
# middle row deleted, (c) its header line's identity kept but a row from another run (idn's row with the same time)
# spliced in; each restarted to the end. Expected: the edit named (the rows compared with the checkpoint, or a digest),
# or the restart's force.dat rewritten from the checkpoint; an edited row kept in the final force.dat without a word =
# SILENT.
. "$(dirname "$0")/../lib.sh"
ik; I=postProcessing/indentation; cd $W; mv ind k0
again() { cd $W; rm -rf ind; cp -a k0 ind; cd ind; }
ed() { /usr/bin/python3 - $I/force.dat "$1" <<'P'
import sys
p, how = sys.argv[1:3]; L = open(p).read().split('\n'); rows = [i for i, l in enumerate(L) if l.strip() and not l.startswith('#')]
if how == 'scale':
    i = rows[-1]; t = L[i].split(); old = t[1]; t[1] = repr(float(t[1]) * 1.5); L[i] = ' '.join(t); print('   row %d force %s -> %s (time %s)' % (i, old, t[1], t[0]))
else:
    i = rows[len(rows) // 2]; print('   row %d deleted: %s' % (i, L[i][:80])); del L[i]
open(p, 'w').write('\n'.join(L))
P
}
one() { tryt 600 "$1" cellIndentationFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | said: $(msg 4 | cut -c1-300)"; echo "   final force.dat rows $(grep -vc '^#' $I/force.dat)"; }
again; ed scale; v=$(grep -v '^#' $I/force.dat | tail -1 | awk '{print $2}'); one "(a) force.dat's last row x1.5, restart"; echo "   the edited value $v still in force.dat: $(grep -c -- "$v" $I/force.dat)"
again; ed del; one "(b) a middle row of force.dat deleted, restart"
