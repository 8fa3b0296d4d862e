#!/bin/bash
# d25 (class 2, paperFigures -output over a user folder, and -output a file): the user files kept (a refusal or figures beside them), a file at -output not replaced by a folder silently.
. "$(dirname "$0")/../lib.sh"
cp -r $ROOT/tutorials/paper $W/paper; cd $W/paper; mkdir -p $W/figs; echo precious > $W/figs/notes.txt; echo precious2 > $W/figfile
tryt 200 "(a) -output a folder with a user file, -noRun" paperFigures -noRun -output $W/figs; echo "   figs: $(ls $W/figs | head -20 | tr "\n" " "); notes: $(cat $W/figs/notes.txt 2>&1)"
tryt 200 "(b) -output a file" paperFigures -noRun -output $W/figfile; echo "   figfile: $(file -b $W/figfile 2>&1 | cut -c1-40) $(cat $W/figfile 2>&1 | head -1)"
