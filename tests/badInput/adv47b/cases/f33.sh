#!/bin/bash
# f33 (class 2, paperFigures' output over a user's folder): paperFigures -noRun -output $W/mine (holding a user's README.md and results.json) -results $W/empty (an empty tree: no run current): refused naming what is missing and/or the folder, the user's two files unchanged; never replaced.
. "$(dirname "$0")/../lib.sh"
cp -r $ROOT/tutorials/paper $W/paper; cd $W/paper; mkdir -p $W/mine $W/empty; echo "mine: my notes" > $W/mine/README.md; echo '{"mine": 1}' > $W/mine/results.json
tryt 120 "-noRun -output mine -results empty" paperFigures -noRun -output $W/mine -results $W/empty; kept_() { grep -l "$1" $W/mine/* 2>/dev/null | tr '\n' ' '; }; echo "   mine: README '$(kept_ 'mine: my notes')' results '$(kept_ '"mine"')' files: $(ls $W/mine | tr '\n' ' ')"
