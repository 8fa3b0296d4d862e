#!/bin/bash
# d16 (class 1, must be ACCEPTED or clearly refused: a finished indentation with a row appended to the protocol, restart latestTime): the new row runs (force.dat grows, peaks.dat a new row) or a message says how to continue; never exit 0 with nothing done and no word.
. "$(dirname "$0")/../lib.sh"
idn; latest; n0=$(grep -vc "^#" postProcessing/indentation/force.dat); p0=$(grep -vc "^#" postProcessing/indentation/peaks.dat)
python3 - constant/indenterProperties <<P
import re,sys; p=sys.argv[1]; t=open(p).read(); i=t.index("protocol"); j=t.index(");", i); open(p,"w").write(t[:j]+"    (D load 10e-6 0.3e-6)\n"+t[j:])
P
grep -A8 "^protocol" constant/indenterProperties | tr "\n" " "; echo
tryt 200 "restart with a new row" cellIndentationFoam; cont; echo "   force rows $n0 -> $(grep -vc "^#" postProcessing/indentation/force.dat); peaks rows $p0 -> $(grep -vc "^#" postProcessing/indentation/peaks.dat)"; tail -3 $W/try.log | cut -c1-200
