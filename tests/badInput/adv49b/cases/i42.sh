#!/bin/bash
# i42 (class 2/DATALOSS, calibrateCell's -work over folders it did not make): the shortened calibration (as i41) with -work
# (a) a folder of the user's holding files (notes.txt, data/x.csv), (b) the case folder itself, (c) the folder holding the
# case ($W), (d) a symbolic link to a user's folder, each SIGTERMed after 60 s if it runs: refused before anything is
# written, naming -work, or run without removing or changing any file of the user's (checked after).
. "$(dirname "$0")/../lib.sh"
cal; sed -i 's/^maxIterations .*/maxIterations 1;/; s/^nProcs .*/nProcs 1;/' system/calibrationDict; C=$PWD
mkdir -p $W/user/data; echo note > $W/user/notes.txt; echo 1,2 > $W/user/data/x.csv; ln -s $W/user $W/ulink; find $W -type f ! -path "$W/w*" | sort | xargs md5sum > $W/all0 2>/dev/null
for wk in $W/user $C $W $W/ulink; do tryt 60 "-work $wk" calibrateCell -work $wk; killIn $W/cal; sleep 0.5
  echo "   user files changed or lost: $(md5sum -c --quiet $W/all0 2>&1 | grep -v 'try.log\|/log\.' | cut -c1-200 | tr '\n' ' ')"; done
