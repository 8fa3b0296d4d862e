#!/bin/bash
# d24 (class 2, calibrateCell -work over folders not its own): (a) -work a folder holding a user file; (b) -work . (the case itself); (c) -work naming an existing file: each refused before anything, the user file, the case and the file unchanged.
. "$(dirname "$0")/../lib.sh"
cal; sums > ../s0; mkdir -p $W/work; echo precious > $W/work/notes.txt; echo precious2 > $W/afile
tryt 60 "(a) -work folder with a user file" calibrateCell -work $W/work; echo "   notes.txt: $(cat $W/work/notes.txt 2>&1); work: $(ls -a $W/work | tr "\n" " ")"
tryt 60 "(b) -work ." calibrateCell -work .; nochange ../s0
tryt 60 "(c) -work a file" calibrateCell -work $W/afile; echo "   afile: $(cat $W/afile 2>&1)"
