#!/bin/bash
# i47 (class 3, the main job run twice at once): T = a copy of the tutorials folder in a copy of the project made of links
# to every other top-level entry (since P1b: the main job sources ../etc/bashrc, absent beside a bare copy of tutorials); `T/Allrun` started, and 3 s later a second
# `T/Allrun` (from another directory); the second refused at once naming the first (or each of its case steps refused naming
# the running case); both SIGKILLed (by their working directories under T) after 150 s. No case folder holds the outputs of two
# runs (per case: its logs name one run; the verification cases' time directories carry one commit marker each); no file
# written outside T.
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/proj; for e in "$ROOT"/*; do [ "$(basename $e)" = tutorials ] || ln -s "$e" $W/proj/; done; cp -r "$ROOT/tutorials" $W/proj/tutorials; T=$W/proj/tutorials; mkdir -p $W/u; cd $W/u; touch $W/stamp
$T/Allrun > $W/a1.log 2>&1 & p1=$!; sleep 3; $T/Allrun > $W/a2.log 2>&1 & p2=$!; sleep 20; echo "   second after 20 s: $(kill -0 $p2 2>/dev/null && echo running || echo ended) | $(grep -a -i -m3 'lock\|use\|refus\|running\|already' $W/a2.log | cut -c1-200 | tr '\n' '|')"
sleep 130; killIn $T; kill -KILL $p1 $p2 2>/dev/null; wait; sleep 1
echo "   a1: $(tail -3 $W/a1.log | cut -c1-150 | tr '\n' '|')"; echo "   a2: $(tail -3 $W/a2.log | cut -c1-150 | tr '\n' '|')"
for c in $(find $T -name 'log.*' -newer $W/stamp -printf '%h\n' | sort -u); do echo "   ${c#$T/}: logs $(ls $c | grep -c '^log\.') | markers per time: $(for t in $c/[0-9]*; do [ -d $t ] && ls -a $t | grep -c writeCommitted; done | sort | uniq -c | tr '\n' ' ') | lock: $(head -1 $c/.runLock 2>/dev/null)"; done
echo "   written outside T (in the cwd): $(ls -A $W/u | tr '\n' ' ')"
