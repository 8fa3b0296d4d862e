#!/bin/bash
# f34 (class 4, paperFigures' -output and -results of the wrong kind): (a) -output an existing file, (b) -results a file, (c) -results a folder that does not exist: each refused naming the option and what the path is, rc != 0, no traceback, the file unchanged.
. "$(dirname "$0")/../lib.sh"
cp -r $ROOT/tutorials/paper $W/paper; cd $W/paper; echo "mine" > $W/file.txt
tryt 60 "(a) -output a file" paperFigures -noRun -output $W/file.txt; grep -a -c Traceback $W/try.log
tryt 60 "(b) -results a file" paperFigures -noRun -results $W/file.txt; grep -a -c Traceback $W/try.log
tryt 60 "(c) -results missing" paperFigures -noRun -results $W/nothere; grep -a -c Traceback $W/try.log; cat $W/file.txt
