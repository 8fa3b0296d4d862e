#!/bin/bash
# runOne.sh [-o DIR] PASS ID: adv41's runOne.sh (itself adv40's) for adv42, copied because the earlier runners write into
# their own passes' out/ folders, which this pass must not change: runs tests/badInput/PASS/cases/ID.sh unchanged, from
# its own folder, with this worktree's build, ADV=${ADVPREFIX:-/tmp/adv42-}PASS (base cases), nice -n 10, a 300 s KILL
# timeout, in a session of its own (whatever the case leaves running is SIGKILLed by its group id after it); output
# tests/badInput/adv42/out/DIR/PASS_ID.txt
here=$(cd "$(dirname "$0")" && pwd); d=A; [ "$1" = -o ] && { d=$2; shift 2; }
pass=$1 id=$2; OUT=$here/out/$d; mkdir -p $OUT; f=$OUT/${pass}_$id.txt
cd $here/../$pass || exit 1
start=$(date +%s.%N); pidf=$(mktemp)
ADV=${ADVPREFIX:-/tmp/adv42-}$pass setsid bash -c 'echo $$ > "$0"; exec timeout -s KILL 300 nice -n 10 bash "cases/$1.sh"' $pidf $id > $f 2>&1 < /dev/null; rc=$?
g=$(cat $pidf); rm -f $pidf; left=$(pgrep -g $g | tr '\n' ' '); [ -n "$left" ] && { kill -KILL -- -$g 2>/dev/null; echo "[left running after the case, SIGKILLed: $left]" >> $f; }
echo "[case exit $rc, $(echo "$(date +%s.%N) - $start" | bc | cut -c1-5) s]" >> $f
echo "$(date +%H:%M:%S) $pass $id rc=$rc"
