#!/bin/bash
# CASETIMEOUT=300
# u14 (fix19i row "incidentWindow.py's --series rows", varied: odd values of T0 T1 DT, and the boundary): on the finished
# preview with its reference (pwd0): --series 0 2 -1e-3 (DT negative), 0 2 0, 0 2 nan, 0 inf 1, nan 2 1e-3, 2 0 1e-3
# (T1 < T0), 0 100 1e-3 (exactly 100000 rows: taken), 0 100.001 1e-3 (100001: refused), 0 2 1e-320 (denormal), and
# --series given twice. Expected: each refused in one line naming --series and the valid range, or the rows printed;
# a traceback = CRASH (low); a hang (60 s) = HANG; an empty table printed rc 0 for an impossible range = UNCLEAR (low).
. "$(dirname "$0")/../lib.sh"
pwd0
for s in "0 2 -1e-3" "0 2 0" "0 2 nan" "0 inf 1" "nan 2 1e-3" "2 0 1e-3" "0 100 1e-3" "0 100.001 1e-3" "0 2 1e-320" "0 2 1e-3 --series 0 1 1e-3"; do
  iw . --series $s; echo "   rows printed: $(grep -a -c '^ *[0-9]' $W/try.log) | tracebacks $(grep -a -c Traceback $W/try.log) | said: $(grep -a -v '^ *[0-9]' $W/try.log | grep -a -v '^ *$' | tail -1 | cut -c1-220)"; done
