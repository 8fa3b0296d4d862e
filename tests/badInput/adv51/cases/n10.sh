#!/bin/bash
# CASETIMEOUT=300
# n10 (new, class 3: tutorials/calibration/averageCell's Allclean, which removes validationCell/ where predictValidation.py
# runs cellMesh and cellIndentationFoam): a copy of the tutorial ($W/cal, constant/solidProperties.calibrated from its
# solidProperties), predictValidation.py started, and 10 s later (its cellIndentationFoam running, validationCell/.runLock
# held) $W/cal/Allclean. Refused naming the run, nothing removed; never the running case removed under it.
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/calibration/averageCell" $W/cal; cd $W/cal; cp constant/solidProperties constant/solidProperties.calibrated
(/usr/bin/python3 predictValidation.py > $W/pv.log 2>&1; echo "predictValidation rc $?" >> $W/pv.log) & pp=$!; sleep 10
echo "running: $(inDir $W/cal | tr ';' '\n' | grep -v 'n10.sh\|cut ' | tr '\n' ';' | cut -c1-200) | locks: $(ls -a . validationCell 2>/dev/null | grep -c runLock) ($(head -c 120 validationCell/.runLock 2>/dev/null | tr '\n' ' '))"
tryt 60 "(a) calibration Allclean while predictValidation's solver runs" ./Allclean; echo "   validationCell now: $(ls validationCell 2>/dev/null | tr '\n' ' ') | constant: $(ls constant | tr '\n' ' ')"
sleep 5; killIn $W/cal; sleep 1; killIn $W/cal; wait $pp; echo "   predictValidation: $(tail -2 $W/pv.log | tr '\n' ' ' | cut -c1-250)"
