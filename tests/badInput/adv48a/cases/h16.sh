#!/bin/bash
# CASETIMEOUT=600
# h16 (class 4, adv48a h09's pulseStudy row re-checked: h09 was cut before its end): the small study with maxPoints 1
# appended, sampleInterval and strainRateWindow given inf, -inf, nan, -0: each refused (rc 1, no Traceback) naming the
# entry, the file and the valid range with its unit.
. "$(dirname "$0")/../lib.sh"
show() { local rc=$1; echo "   [$2] rc=$rc traceback=$(grep -a -c Traceback $W/try.log) | $(grep -a -m1 -A1 '[Ee]rror' $W/try.log | head -2 | tr '\n' ' ' | tr -s ' ' | cut -c1-330)"; }
study; echo "maxPoints 1;" >> system/pulseStudyDict; cp system/pulseStudyDict ../pd
for k in sampleInterval strainRateWindow; do for v in inf -inf nan -0; do cp ../pd system/pulseStudyDict; sete system/pulseStudyDict $k $v; timeout -s KILL 60 pulseStudy > $W/try.log 2>&1; show $? "$k $v"; killIn $W; done; done
