#!/bin/bash
# g28 (class 2, calibrateCell -work a user's folder) calibrateCell -work $W/mywork (a folder of the user's, with files) (a) with a -dict that does not exist (refused before anything), (b) with the tutorial's dictionary, SIGKILLed after 40 s: the user's files kept in both; never the folder removed or emptied.
. "$(dirname "$0")/../lib.sh"
cal; mkdir $W/mywork; echo "keep me" > $W/mywork/keep.txt; mkdir $W/mywork/sub; echo "keep me too" > $W/mywork/sub/x.txt
tryt 120 "(a) -dict missing" calibrateCell -case . -dict system/nope -work $W/mywork; ls -R $W/mywork | tr '\n' ' '; echo
tryt 40 "(b) killed after 40 s" calibrateCell -case . -work $W/mywork -nProcs 1; killIn $W; ls $W/mywork | tr '\n' ' '; echo; where "keep me" "keep me too"
