#!/bin/bash
# t07: plotBlast.py on a case without results
. "$(dirname "$0")/../lib.sh"
blast; /usr/bin/python3 "$FOAM_TUTORIALS/blast/plotBlast.py" . 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
