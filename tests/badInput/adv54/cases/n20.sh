#!/bin/bash
# CASETIMEOUT=600
# n20 (new, class 1/5: a finished indentation extended by a protocol row - a legitimate restart - then measured, and the
# same row appended to a copy run from the start: the digests of a continued file): idn (finished, protocol A, B, C1
# load, C1 unload); a row `(C2 load 10e-6 0.5e-6)` appended to its protocol, startFrom latestTime, run; plotIndentation.py;
# and the same protocol run from the start in a fresh copy: force.dat, peaks.dat and their sidecars compared. Expected:
# the restart continues (or refuses clearly), its files equal the from-scratch run's (or the difference named), the
# digests check whole; a refusal "edited by hand" of the continued file = UNCLEAR.
. "$(dirname "$0")/../lib.sh"
addRow() { /usr/bin/python3 - constant/indenterProperties <<'P'
import sys
p = sys.argv[1]; t = open(p).read(); k = t.index("(C1  unload"); e = t.index("\n", k); t = t[:e] + "\n    (C2  load    10e-6   0.5e-6)" + t[e:]; open(p, "w").write(t)
P
}
idn; addRow; grep -A7 '^protocol' constant/indenterProperties | tr '\n' ' '; echo; latest; rm -f .runLock; tryt 300 "(a) finished run + a protocol row, restart" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250)"
pi; echo "   (a) $(pk)"; ok_ postProcessing/indentation/force.dat; ok_ postProcessing/indentation/peaks.dat; A=$PWD
cd $W; rm -rf ind; ind; addRow; tryt 300 "(b) the same protocol from the start" cellIndentationFoam; for f in force.dat peaks.dat force.dat.fnv1a64 peaks.dat.fnv1a64; do echo "   $f: $(cmp -s postProcessing/indentation/$f $A/postProcessing/indentation/$f && echo same || echo DIFFERS)"; done
