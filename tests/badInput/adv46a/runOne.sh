#!/bin/bash
# runOne.sh [-o DIR] PASS ID: adv45's runOne.sh for adv46a: runs tests/badInput/PASS/cases/ID.sh unchanged from its own
# folder tests/badInput/PASS (its cases and lib.sh), with this worktree's build, ADV=${ADVPREFIX:-/tmp/adv46a-}PASS (base
# cases), nice -n 10, a 300 s KILL timeout, bin/ first in PATH (its setsid keeps the session); output tests/badInput/adv46a/out/DIR/PASS_ID.txt. Unlike adv45's, no setsid
# (it escapes nice through the session's autogroup): GNU timeout puts itself and the case in a process group of their own
# (setpgid, without --foreground), whatever the case leaves running in that group is SIGKILLed by its group id after it.
here=$(cd "$(dirname "$0")" && pwd); d=A; [ "$1" = -o ] && { d=$2; shift 2; }
pass=$1 id=$2; OUT=$here/out/$d; mkdir -p $OUT; f=$OUT/${pass}_$id.txt
cd $here/../$pass || exit 1
start=$(date +%s.%N); pidf=$(mktemp)
PATH=$here/bin:$PATH ADV=${ADVPREFIX:-/tmp/adv46a-}$pass bash -c 'echo $$ > "$0"; exec timeout -s KILL 300 nice -n 10 bash "cases/$1.sh"' $pidf $id > $f 2>&1 < /dev/null; rc=$?
g=$(cat $pidf); rm -f $pidf; left=$(pgrep -g $g | tr '\n' ' '); [ -n "$left" ] && { kill -KILL -- -$g 2>/dev/null; echo "[left running after the case, SIGKILLed: $left]" >> $f; }
echo "[case exit $rc, $(echo "$(date +%s.%N) - $start" | bc | cut -c1-5) s]" >> $f
echo "$(date +%H:%M:%S) $pass $id rc=$rc load=$(cut -d' ' -f1 /proc/loadavg)"
