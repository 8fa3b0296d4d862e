#!/bin/bash
# t49: plotIndentation.py on a blast case
. "$(dirname "$0")/../lib.sh"
blastDone; /usr/bin/python3 "$FOAM_TUTORIALS/indentation/plotIndentation.py" . 2>&1 | tail -2; echo "rc=${PIPESTATUS[0]}"
