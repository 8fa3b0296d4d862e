#!/bin/bash
# CASETIMEOUT=600
# p35 (new, class 3: p25 for the indentation, whose force.dat is appended in place): the killed smoke indentation A (ik)
# and B, a copy of A whose postProcessing/ is a symbolic link to A's postProcessing/ (results kept in one place); both
# restarted at once (B 1 s after A). Expected: B refused (the results folder in use by A's run: its lock, or the real
# path of what it writes), or A's results whole (force.dat without rows of B's run, no duplicated times); force.dat with
# both runs' rows = DATALOSS.
. "$(dirname "$0")/../lib.sh"
ik; cd $W; mv ind A; cp -a A B; cd B; rm -rf postProcessing; ln -s $W/A/postProcessing postProcessing; cd $W
(cd A; cellIndentationFoam > log.A 2>&1; echo "A rc $?" >> log.A) & pa=$!; sleep 1
cd $W/B; tryt 300 "(a) B (postProcessing a link to A's) restarted 1 s after A" cellIndentationFoam; wait $pa
echo "   A: $(tail -1 $W/A/log.A) $(grep -a -m1 -i 'fatal' -A2 $W/A/log.A | tr '\n' ' ' | cut -c1-200) | B: End $(grep -a -c '^End' $W/try.log) $(msg 3 | cut -c1-250)"
F=$W/A/postProcessing/indentation/force.dat; echo "   A's force.dat: rows $(grep -vc '^#' $F), duplicated times $(grep -v '^#' $F | awk '{print $1}' | sort | uniq -d | wc -l), non-increasing $(grep -v '^#' $F | awk 'NR>1 && $1<=p {n++} {p=$1} END {print n+0}'), header lines $(grep -c '^#' $F)"
