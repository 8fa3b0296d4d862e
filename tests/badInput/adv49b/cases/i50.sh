#!/bin/bash
# i50 (class 4, Allrun numbers at the edges of the ranges it prints): in a fresh preview copy each refused option's message is
# read for its range, then the value at the edge and one ulp beyond: -amplitude 1e9 and 1.0000000000000002e9 (range (0, 1e9]),
# -membraneLayers 20 and 21, -solidSubcycles 1000 and 1001, -motionDistance 1e-300 and 1e-301, -pulse (at the lower edge
# the message prints); each beyond-edge value refused naming the option and the range it prints; each edge value accepted
# by the option check (the step after it may refuse it for another reason, named).
. "$(dirname "$0")/../lib.sh"
prev; sums > ../s0
for a in "-amplitude 1.0000000000000002e9" "-amplitude 0" "-membraneLayers 21" "-solidSubcycles 1001" "-motionDistance 1e-301" "-pulse 0" "-pulse -1e-9" "-writeInterval 0"; do
  eval "tryt 120 \"$a\" ./Allrun $PREV -noRun $a"; echo "   changed: $(changed ../s0)"; done
for a in "-amplitude 1e9" "-membraneLayers 20" "-solidSubcycles 1000" "-motionDistance 1e-300"; do
  ./Allclean > /dev/null 2>&1; tryt 300 "$a" ./Allrun $PREV -noRun $a; echo "   $(grep -a -h -o "$(echo ${a% *} | sed 's/^-//')[^;]*;" system/*.allrun constant/*.allrun 2>/dev/null | head -2 | tr '\n' ' ') | logs: $(ls log.* 2>/dev/null | tr '\n' ' ')"; done
