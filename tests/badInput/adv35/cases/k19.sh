#!/bin/bash
# k19: ind: force.dat with 40 bytes zeroed, plotIndentation.py
. "$(dirname "$0")/../lib.sh"
indDone; dd if=/dev/zero of=postProcessing/indentation/force.dat bs=1 count=40 seek=$(($(stat -c%s postProcessing/indentation/force.dat)*50/100)) conv=notrunc 2>/dev/null
/usr/bin/python3 "$FOAM_TUTORIALS/indentation/plotIndentation.py" . > log.p 2>&1; rc=$?; tail -4 log.p; echo "rc=$rc"
