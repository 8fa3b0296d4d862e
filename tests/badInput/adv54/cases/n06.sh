#!/bin/bash
# CASETIMEOUT=600
# n06 (new, class 2/5: two runs writing one result through a hard-linked copy, and -overwrite over digested results):
# (a) ik (killed indentation), copied with `cp -al` (a user's quick "backup" or second case sharing the files), the COPY
# restarted to its end: the original's force.dat, peaks.dat and their SIDECARS unchanged (md5) and checkable? (fix19i's
# ownCopy covers force.dat and peaks.dat); (b) idn (finished), `cellIndentationFoam -overwrite` with maxDepthIncrement
# 0.05e-6: plotIndentation.py on the new results, and the earlier run's files moved aside still checkable?
# Expected: (a) the original kept whole (else DATALOSS); (b) the new results measured, the old kept or refused clearly.
. "$(dirname "$0")/../lib.sh"
ik; d=postProcessing/indentation; cd $W; cp -al ind ind2; (cd ind; md5sum $d/* > $W/md5a); cd ind2; latest; rm -f .runLock
tryt 400 "(a) the cp -al copy restarted" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log)"
cd $W/ind; md5sum -c $W/md5a 2>&1 | grep -v ': OK' | sed 's/^/   original: /'; echo "   original's links: $(stat -c '%n %h' $d/* | tr '\n' ' ')"; ok_ $d/force.dat; ok_ $d/peaks.dat
cd $W; rm -rf ind ind2; idn; ls -a $d | tr '\n' ' '; echo; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.05e-6/' constant/indenterProperties
tryt 400 "(b) -overwrite with a changed step" cellIndentationFoam -overwrite; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(grep -a -i -m2 'overwr\|aside\|moved' $W/try.log | tr '\n' '|' | cut -c1-300)"
pi; echo "   (b) $(pk)"; ls -a . $d | tr '\n' ' '; echo; for f in $(find . -name 'force.dat' -path '*overwritten*' 2>/dev/null); do ok_ $f; done
