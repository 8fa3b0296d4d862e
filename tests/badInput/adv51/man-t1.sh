#!/bin/bash
# t1.sh (adv51, by hand, n06 (b) cleaner): two predictValidation.py 8 s apart in a copy of the calibration tutorial; the
# first's state 25 s after the second started, before anything is killed
cd /tmp/adv51-man/cal
nice -n 10 /usr/bin/python3 predictValidation.py > first.log 2>&1 & f=$!
sleep 8; echo "before second: $(ls validationCell | tr '\n' ' ') | first's solver: $(pgrep -P $f -a | cut -c1-80)"
nice -n 10 /usr/bin/python3 predictValidation.py > second.log 2>&1 & s=$!
sleep 25; echo "first alive: $(kill -0 $f 2>/dev/null && echo yes || echo no) | first.log: $(tail -2 first.log | tr '\n' ' ' | cut -c1-200)"
echo "second alive: $(kill -0 $s 2>/dev/null && echo yes || echo no) | second.log: $(tail -2 second.log | tr '\n' ' ' | cut -c1-200)"
echo "processes with cwd in cal: $(for d in /proc/[0-9]*; do c=$(readlink $d/cwd 2>/dev/null); case "$c" in /tmp/adv51-man/cal*) echo -n "${d#/proc/}:$(tr '\0' ' ' < $d/cmdline | cut -c1-40) ($c) ";; esac; done)"
for p in $(pgrep -P $f) $(pgrep -P $s) $f $s; do kill -KILL $p 2>/dev/null; done
