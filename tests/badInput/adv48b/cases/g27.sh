#!/bin/bash
# g27 (class 2, paperFigures -output into a user's folder) paperFigures -noRun -output $W/mine where mine holds the user's README.md, results.json and notes.txt: refused before writing, naming the files, or the user's files kept (aside, said); never replaced silently.
. "$(dirname "$0")/../lib.sh"
cp -r $ROOT/tutorials/paper $W/paper; cd $W/paper; mkdir $W/mine; echo "my own notes" > $W/mine/README.md; echo '{"mine": 1}' > $W/mine/results.json; echo "notes" > $W/mine/notes.txt
tryt 300 "paperFigures -noRun -output mine" paperFigures -noRun -output $W/mine; tail -3 $W/try.log | cut -c1-200; ls $W/mine | tr '\n' ' '; echo; where "my own notes" '{"mine": 1}'
