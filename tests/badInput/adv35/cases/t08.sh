#!/bin/bash
# t08: plotBlast.py with an empty solidProbes file
. "$(dirname "$0")/../lib.sh"
blastDone; : > $(ls postProcessing/solidProbes/0/*); /usr/bin/python3 "$FOAM_TUTORIALS/blast/plotBlast.py" . 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
