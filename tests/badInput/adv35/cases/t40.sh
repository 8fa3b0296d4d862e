#!/bin/bash
# t40: plotIndentation.py with peaks.dat holding a garbage row
. "$(dirname "$0")/../lib.sh"
indDone; echo "C9 abc def ghi" >> postProcessing/indentation/peaks.dat; /usr/bin/python3 "$FOAM_TUTORIALS/indentation/plotIndentation.py" . 2>&1 | tail -2; echo "rc=${PIPESTATUS[0]}"
