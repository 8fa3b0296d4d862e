#!/bin/bash
# i29 (class 3, two preview Allruns at once in one case, and one from another directory): a fresh preview copy; `./Allrun
# $PREV -endTime 2e-9` started twice 0.3 s apart: the second refused naming the first (the Allrun's lock), the first exit 0
# with one set of results (times 1e-09 2e-09, each with one marker). Then (b) `cd /tmp/adv49b-cwd-XXX && <case>/Allrun
# $PREV -endTime 3e-9` (a later endTime: refused as other options, naming -endTime and Allclean) writes nothing in the cwd.
. "$(dirname "$0")/../lib.sh"
prev; ./Allrun $PREV -endTime 2e-9 > ../log.a1 2>&1 & p1=$!; sleep 0.3; run 200 ./Allrun $PREV -endTime 2e-9 > ../log.a2 2>&1; echo "   second: $(grep -a -i -m2 'lock\|use\|refus\|running\|already' ../log.a2 | cut -c1-200 | tr '\n' '|')"
wait $p1; echo "   first exit $? | $(tail -1 ../log.a1 | cut -c1-150)"; after; echo "   markers: $(ls -d */.writeCommitted | tr '\n' ' ')"
C=$PWD; D=$(mktemp -d /tmp/adv49b-cwd-XXX); cd $D; echo user > note.txt; tryt 200 "(b) Allrun from another directory, -endTime 3e-9" $C/Allrun $PREV -endTime 3e-9; echo "   cwd now: $(ls -A | tr '\n' ' ')"; cd $C; after; rm -rf $D
