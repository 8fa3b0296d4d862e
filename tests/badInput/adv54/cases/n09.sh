#!/bin/bash
# CASETIMEOUT=300
# n09 (new, class 2: the plot scripts' outputs over a user's files of the same name): (a) idn with a user's results.md
# (the user's own notes on the run) and indentation.png in the case: plotIndentation.py; (b) bd with a user's fig10.png
# and postProcessing/blastSummary.dat: plotBlast.py. Expected: the user's files kept (refused, or written beside them),
# or replaced only as the documented outputs (then "low": the scripts' docstrings name these files).
. "$(dirname "$0")/../lib.sh"
idn; mark results.md; mark indentation.png; pi; kept_ results.md; kept_ indentation.png
cd $W; bd; mark fig10.png; mark postProcessing/blastSummary.dat; tryt 300 "(b) plotBlast.py ." /usr/bin/python3 $ROOT/tutorials/blast/plotBlast.py .; kept_ fig10.png; kept_ postProcessing/blastSummary.dat
