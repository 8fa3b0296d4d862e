#!/bin/bash
# w117: sod: riemannError run again after the user changed the states in system/riemannProblemDict (right p 1e4 -> 2e4) after the run: compares the run with the exact answer of another problem, without a word?
. "$(dirname "$0")/../lib.sh"
sodDone; riemannError -latestTime > log.re0 2>&1; echo "before rc=$?"; grep -a -i "L1\|star" log.re0 | head -3 | cut -c1-200
/usr/bin/python3 - <<'P'
import re; s=open('system/riemannProblemDict').read(); i=s.index('right'); s=s[:i]+s[i:].replace('p       1e4;','p       2e4;',1); open('system/riemannProblemDict','w').write(s)
P
grep -A4 "^right" system/riemannProblemDict | tr -s ' \n' ' '; echo; try after riemannError -latestTime; grep -a -i "L1\|star\|changed\|differ" $W/try.log | head -4 | cut -c1-200
