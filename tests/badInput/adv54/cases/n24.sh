#!/bin/bash
# CASETIMEOUT=300
# n24 (new, class 5: n01's appended peaks.dat row through the other reader of peaks.dat, tutorials/indentation/
# plotFields.py, which picks solid.h5's step at the label's time): idn; a row "C1,i 1.05 5e-07 1.5e-09" appended to
# peaks.dat (the label again, at another time); plotFields.py . C1,i. Expected: refused (a row the run did not write); the
# field plotted at the hand row's time (1.05 s) or its force taken, without a word = SILENT.
. "$(dirname "$0")/../lib.sh"
idn; tryt 200 "(0) plotFields.py . C1,i" /usr/bin/python3 $ROOT/tutorials/indentation/plotFields.py . C1,i; echo "   said: $(say 1 | cut -c1-200) | $(grep -a -i 'time\|step\|t =' $W/try.log | head -2 | tr '\n' '|' | cut -c1-250)"
echo 'C1,i 1.05 5e-07 1.5e-09' >> postProcessing/indentation/peaks.dat; tryt 200 "(a) peaks.dat + a C1,i row at 1.05 s" /usr/bin/python3 $ROOT/tutorials/indentation/plotFields.py . C1,i; echo "   said: $(say 1 | cut -c1-200) | $(grep -a -i 'time\|step\|t =' $W/try.log | head -2 | tr '\n' '|' | cut -c1-250)"
