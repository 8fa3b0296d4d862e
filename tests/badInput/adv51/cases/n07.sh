#!/bin/bash
# CASETIMEOUT=900
# n07 (new, class 4/5: planeWave's less used options; the corpus has 0-2 cases of -reference, -except, -radius, -layered,
# -endTime): the finished preview with planeWave's reference (pwd0): (a) -reference of a file that is not a reference
# (controlDict), an empty file, another case's reference of another pulse (the preview's reference with its pressures
# doubled), a reference cut mid-line; (b) -except nosuch, -except '' ; (c) -radius nan, 0, -1e-6, 1e300; (d) -endTime
# 1e-10 (before the run's end), nan; (e) -probes solid, -probes nosuch. Each refused rc != 0 in one line naming the
# option and its value (or the file and what is wrong), or measured; never a traceback, never the user's reference file
# changed, never measures written from a foreign reference without a word.
. "$(dirname "$0")/../lib.sh"
tb() { echo "   traceback: $(grep -a -c '^Traceback' $W/try.log) | last: $(grep -av '^ *$' $W/try.log | tail -2 | tr '\n' ' ' | cut -c1-300)"; }
pwd0; P=$PWD; R=postProcessing/planeWave/0/reference.dat; cp $R $W/ref.dat; md5sum $R > $W/ref.md5
pw() { local l=$1; shift; tryt 300 "$l" planeWave -case $P "$@"; tb; md5sum -c --quiet $W/ref.md5 > /dev/null 2>&1 || echo "   reference.dat CHANGED"; }
pw "(a) -reference system/controlDict" -reference $P/system/controlDict
: > $W/empty.dat; pw "(a) -reference an empty file" -reference $W/empty.dat
/usr/bin/python3 - $W/ref.dat $W/ref2.dat <<'P'
import sys
out = []
for l in open(sys.argv[1]):
    if l.startswith('#') or not l.strip(): out.append(l); continue
    f = l.split(); out.append(' '.join([f[0]] + ['%.10g' % (2 * float(x)) for x in f[1:]]) + '\n')
open(sys.argv[2], 'w').write(''.join(out))
P
pw "(a) -reference of another pulse (pressures doubled)" -reference $W/ref2.dat; echo "   measures: $(grep -v '^#' $P/postProcessing/planeWave/0/measures.dat 2>/dev/null | head -2 | tr -s ' ' | cut -c1-200)"
n=$(wc -l < $W/ref.dat); head -$((n/2)) $W/ref.dat > $W/ref3.dat; sed -n "$((n/2+1))p" $W/ref.dat | cut -c1-9 >> $W/ref3.dat; pw "(a) -reference cut mid-line" -reference $W/ref3.dat
pw "(b) -except nosuch" -except nosuch
pw "(b) -except ''" -except ""
for r in nan 0 -1e-6 1e300; do pw "(c) -radius $r" -radius $r; done
for e in 1e-10 nan; do pw "(d) -endTime $e" -endTime $e; done
pw "(e) -probes solid" -probes solid
pw "(e) -probes nosuch" -probes nosuch
