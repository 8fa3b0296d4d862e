#!/bin/bash
# runOne.sh [-o DIR] PASS ID: runs tests/badInput/PASS/cases/ID.sh (unchanged, from its own folder, as that pass's runner
# does) with this worktree's build, ADV=/tmp/adv40-PASS (its base cases); ADVPREFIX=/tmp/adv40C- for phase C: base cases of the merged build, under nice -n 10 and a 300 s KILL timeout, in a
# session of its own (what the case leaves running is SIGKILLed by that session's group id after it); output in
# tests/badInput/adv40/out/DIR/PASS_ID.txt (DIR: A). Needs no change to the earlier passes' runners (their runners write
# into the earlier passes' own out/ folders, which this pass must not change).
here=$(cd "$(dirname "$0")" && pwd); d=A; [ "$1" = -o ] && { d=$2; shift 2; }
pass=$1 id=$2; OUT=$here/out/$d; mkdir -p $OUT; f=$OUT/${pass}_$id.txt
cd $here/../$pass || exit 1
start=$(date +%s.%N); pidf=$(mktemp)
ADV=${ADVPREFIX:-/tmp/adv40-}$pass setsid bash -c 'echo $$ > "$0"; exec timeout -s KILL 300 nice -n 10 bash "cases/$1.sh"' $pidf $id > $f 2>&1 < /dev/null; rc=$?
g=$(cat $pidf); rm -f $pidf; left=$(pgrep -g $g | tr '\n' ' '); [ -n "$left" ] && { kill -KILL -- -$g 2>/dev/null; echo "[left running after the case, SIGKILLed: $left]" >> $f; }
echo "[case exit $rc, $(echo "$(date +%s.%N) - $start" | bc | cut -c1-5) s]" >> $f
echo "$(date +%H:%M:%S) $pass $id rc=$rc"
