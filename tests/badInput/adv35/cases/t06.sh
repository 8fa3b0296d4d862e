#!/bin/bash
# t06: plotIndentation.py on a case without results
. "$(dirname "$0")/../lib.sh"
ind; /usr/bin/python3 "$FOAM_TUTORIALS/indentation/plotIndentation.py" . 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
