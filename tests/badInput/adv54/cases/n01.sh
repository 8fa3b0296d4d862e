#!/bin/bash
# CASETIMEOUT=300
# n01 (new, class 5: rows appended at a line boundary to a finished run's digested results): the finished smoke
# indentation (idn), plotIndentation.py after (a) one row appended to peaks.dat: "C1,i 2.06 8e-07 1.5e-09" (the label
# again, 1.5 nN instead of the run's 0.99 nN), (b) `cat` of another run's peaks.dat (the same base: a user merging two
# runs' results) onto peaks.dat, (c) one row appended to force.dat (a later time, 5 nN), (d) (a) with the package's check
# itself (resultDigest.check's answer). Expected: each refused naming the file and the first row the run did not write
# (the run is finished: its sidecar covers every row it wrote); the hand row tabled without a word = SILENT.
. "$(dirname "$0")/../lib.sh"
idn; cp -a . $W/i0; pi; echo "   (0) the run as written: $(pk)"
echo 'C1,i 2.06 8e-07 1.5e-09' >> postProcessing/indentation/peaks.dat; pi; echo "   (a) peaks.dat + a C1,i row: $(pk)"; ok_ postProcessing/indentation/peaks.dat
cd $W; rm -rf ind; cp -a i0 ind; cd ind; cat $W/i0/postProcessing/indentation/peaks.dat >> postProcessing/indentation/peaks.dat; pi; echo "   (b) peaks.dat + another run's peaks.dat: $(pk)"
cd $W; rm -rf ind; cp -a i0 ind; cd ind; last=$(grep -v '^#' postProcessing/indentation/force.dat | tail -n 1); echo "   force.dat's last row: $last"
echo "$last" | awk '{ $1 = $1 + 0.01; $3 = 5e-09; print }' >> postProcessing/indentation/force.dat; tail -n 1 postProcessing/indentation/force.dat; pi; echo "   (c) force.dat + a row: $(pk)"; ok_ postProcessing/indentation/force.dat
