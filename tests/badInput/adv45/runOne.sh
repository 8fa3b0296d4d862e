#!/bin/bash
# runOne.sh [-o DIR] PASS ID: adv44's runOne.sh (adv43's, ...) for adv45, with its own out/ folder and base-case prefix:
# runs tests/badInput/PASS/cases/ID.sh unchanged from its own folder (PASS adv45: this folder; any other: tests/badInput/PASS, its own cases and lib.sh), with this
# worktree's build, ADV=${ADVPREFIX:-/tmp/adv45-}PASS (base cases), nice -n 10, a 300 s KILL timeout, in a session of its
# own (whatever the case leaves running is SIGKILLed by its group id after it); output tests/badInput/adv45/out/DIR/PASS_ID.txt
here=$(cd "$(dirname "$0")" && pwd); d=A; [ "$1" = -o ] && { d=$2; shift 2; }
pass=$1 id=$2; OUT=$here/out/$d; mkdir -p $OUT; f=$OUT/${pass}_$id.txt
if [ $pass = adv45 ]; then cd $here; elif [ -d $here/$pass/cases ]; then cd $here/$pass; else cd $here/../$pass || exit 1; fi
start=$(date +%s.%N); pidf=$(mktemp)
ADV=${ADVPREFIX:-/tmp/adv45-}$pass setsid bash -c 'echo $$ > "$0"; exec timeout -s KILL 300 nice -n 10 bash "cases/$1.sh"' $pidf $id > $f 2>&1 < /dev/null; rc=$?
g=$(cat $pidf); rm -f $pidf; left=$(pgrep -g $g | tr '\n' ' '); [ -n "$left" ] && { kill -KILL -- -$g 2>/dev/null; echo "[left running after the case, SIGKILLed: $left]" >> $f; }
echo "[case exit $rc, $(echo "$(date +%s.%N) - $start" | bc | cut -c1-5) s]" >> $f
echo "$(date +%H:%M:%S) $pass $id rc=$rc"
