#!/bin/bash
# i46 (class 2/3, a case's Allclean from another directory and twice at once; rewritten after P1: the tutorials folder has no
# top-level Allclean, so P1's T/Allclean was "command not found"): the preview prepared and run by `./Allrun $PREV -endTime
# 2e-9` in $W/c: (a) `$W/c/Allclean` run by its path from a user's folder holding 0/U, constant/polyMesh/points, log.x,
# postProcessing/n.txt: the case cleaned, nothing of the cwd removed; (b) run again to 2e-9, then two `$W/c/Allclean` at once:
# both exit 0 (or one refused naming the other), the case clean, no error trace; (c) `$W/c/Allclean` and `$W/c/Allrun $PREV
# -endTime 2e-9` started 0.2 s apart: one refused naming the other, the case left either clean or with a whole run (its
# times committed), never half-removed results.
. "$(dirname "$0")/../lib.sh"
prev; C=$PWD; run 300 ./Allrun $PREV -endTime 2e-9 > ../log.a1 2>&1; after
mkdir -p $W/u/0 $W/u/constant/polyMesh $W/u/postProcessing; cd $W/u; for f in 0/U constant/polyMesh/points log.x postProcessing/n.txt; do echo u > $f; done; find . -type f | sort > ../u0
tryt 120 "(a) <case>/Allclean from a user's folder" $C/Allclean; echo "   user files lost: $(find . -type f | sort | comm -23 ../u0 - | tr '\n' ' ') | case now: $(ls -A $C | tr '\n' ' ')"
(cd $C && run 300 ./Allrun $PREV -endTime 2e-9 > ../log.a2 2>&1); $C/Allclean > $W/c1.log 2>&1 & p=$!; $C/Allclean > $W/c2.log 2>&1; r2=$?; wait $p; r1=$?
echo "   (b) two at once: exits $r1 $r2 | $(cat $W/c1.log $W/c2.log | grep -a -v '^ *$' | head -4 | cut -c1-200 | tr '\n' '|') | case now: $(ls -A $C | tr '\n' ' ')"
(cd $C && run 300 ./Allrun $PREV -endTime 2e-9 > ../log.a3 2>&1); $C/Allclean > $W/c3.log 2>&1 & p=$!; sleep 0.2; (cd $C && run 300 ./Allrun $PREV -endTime 2e-9 > $W/a4.log 2>&1); r4=$?; wait $p; r3=$?
echo "   (c) Allclean and Allrun at once: exits $r3 $r4 | $(cat $W/c3.log $W/a4.log | grep -a -i 'lock\|use\|refus\|error' | head -3 | cut -c1-200 | tr '\n' '|')"; cd $C; after; echo "   markers: $(ls -d */.writeCommitted 2>/dev/null | tr '\n' ' ') | logs: $(ls log.* 2>/dev/null | tr '\n' ' ')"
