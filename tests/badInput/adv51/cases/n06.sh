#!/bin/bash
# CASETIMEOUT=600
# n06 (new, class 2/3: tutorials/calibration/averageCell/predictValidation.py, step 2 of that tutorial's Allrun, which a
# user re-runs by hand after calibrateCell): a copy of the calibration tutorial in $W/cal (the script works in its own
# folder), constant/solidProperties.calibrated = the tutorial's solidProperties (a calibrated set stands in), and an
# earlier prediction's results in validationCell/ (results.md, log.cellIndentationFoam and a user's notes.txt):
# (a) predictValidation.py re-run and killed after 20 s (a failed re-run): are the earlier results and the user's file
# still there? (b) two predictValidation.py at once, the second 8 s after the first: does the second remove the case the
# first is running in? Never an earlier result or a user's file lost by a failed re-run; one run per case.
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/calibration/averageCell" $W/cal; cd $W/cal; cp constant/solidProperties constant/solidProperties.calibrated
early() { rm -rf validationCell; mkdir -p validationCell/postProcessing/indentation; echo "earlier prediction: C1,i 11.4 nN" > validationCell/results.md; echo "user's notes" > validationCell/notes.txt; echo "End" > validationCell/log.cellIndentationFoam; }
kept() { echo "   validationCell: $(cd validationCell 2>/dev/null && ls | tr '\n' ' ') | results.md: $(head -1 validationCell/results.md 2>/dev/null | cut -c1-60) | notes.txt: $(cat validationCell/notes.txt 2>/dev/null)"; }
early; tryt 20 "(a) predictValidation.py re-run, killed after 20 s" /usr/bin/python3 predictValidation.py; killIn $W/cal; sleep 1; killIn $W/cal; kept
early; (/usr/bin/python3 predictValidation.py > $W/first.log 2>&1; echo "first rc $?" >> $W/first.log) & fp=$!; sleep 8
echo "   first run's case before the second: $(ls validationCell | tr '\n' ' ') | running: $(inDir $W/cal | cut -c1-200)"
tryt 30 "(b) a second predictValidation.py 8 s after the first" /usr/bin/python3 predictValidation.py; echo "   second: $(tail -2 $W/try.log | tr '\n' ' ' | cut -c1-250)"
sleep 5; killIn $W/cal; sleep 1; killIn $W/cal; wait $fp; echo "   first: $(tail -3 $W/first.log | tr '\n' ' ' | cut -c1-300)"; kept
