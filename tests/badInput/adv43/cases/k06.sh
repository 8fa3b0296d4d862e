#!/bin/bash
# k06 (class 2, files NAMED like our logs in the wrong places, indentation): a finished indentation; the user's coupling.dat (plain text) and solid.h5.mine in postProcessing/indentation/, force.dat (plain text) in postProcessing/myAnalysis/ and in postProcessing/; a notes.txt in the time directory the run wrote (if any); -overwrite: all kept or refused by name?
. "$(dirname "$0")/../lib.sh"
indDone; D=postProcessing/indentation; echo "k06 coupling" > $D/coupling.dat; echo "k06 h5 mine" > $D/solid.h5.mine; mkdir -p postProcessing/myAnalysis; echo "k06 force in myAnalysis" > postProcessing/myAnalysis/force.dat; echo "k06 force top" > postProcessing/force.dat
t=$(ls -d [1-9]* 2>/dev/null | tail -1); [ -n "$t" ] && echo "k06 time note" > $t/notes.txt; echo "   times: $(ls -d [0-9]* 2>/dev/null | tr '\n' ' ')"
restart0; sums > ../s; tryf "-overwrite" cellIndentationFoam -overwrite; grep -a 'postProcessing\|notes' $W/try.log | grep -v '^-->' | head -5 | cut -c1-160; nochange ../s; kept "k06 coupling" "k06 h5 mine" "k06 force in myAnalysis" "k06 force top" "k06 time note"
