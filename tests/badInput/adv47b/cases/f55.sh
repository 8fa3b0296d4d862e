#!/bin/bash
# f55 (class 6, a sweep of 1e4 values): sweepCase on the sod case over 10000 values of maxCo (1e5 values do not fit one argument: "Argument list too long"): refused before any run naming the count and a limit (as pulseStudy's maxPoints), or, if it starts runs, it must not grow without bound; judged after 60 s (rc, runs started, memory).
# (corrected before its first run: -values are space separated and -output is <name>=<file>:/<regex>/, docs/results/calibration.md)
# (corrected after its first run: the output was the case's own controlDict, which sweepCase rightly refuses as not written by the run; now the end time's uniform/time)
. "$(dirname "$0")/../lib.sh"
sod; tryt 60 "two values, comma" sweepCase -entry system/controlDict/maxCo -values "0.4 0.5" -run rhoRiemannFoam -output "t=0.007/uniform/time:/value +([0-9.e+-]+);/" -name two
v=$(/usr/bin/python3 -c "print(' '.join('%.8g' % (0.1 + 0.8 * i / 10000) for i in range(10000)))"); echo "   values: ${#v} characters"
sweepCase -entry system/controlDict/maxCo -values "$v" -run rhoRiemannFoam -output "t=0.007/uniform/time:/value +([0-9.e+-]+);/" -name many > ../log.many 2>&1 & p=$!; sleep 60; echo "   after 60 s: running $(kill -0 $p 2>/dev/null && echo yes || echo no), RSS $(ps -o rss= -p $p 2>/dev/null) KiB, run folders $(ls -d $W/*sweep* 2>/dev/null | wc -l)"; head -3 ../log.many | cut -c1-250; killIn $W; kill -KILL $p 2>/dev/null
