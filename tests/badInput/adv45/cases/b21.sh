#!/bin/bash
# b21 (class 2+4, paperFigures -output over the user's files): a copy of tutorials/paper; (a) -noRun -output $W/mine (the user's folder: README.md, results.json, fig.png of their own); (b) -noRun -output . (the case itself: the tutorial's README.md); (c) -output naming a FILE; (d) -output under a read-only folder: each refused or failed (the runs are missing: -noRun) with the user's files unchanged, no traceback?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/paper" $W/paper; cd $W/paper; mkdir -p $W/mine $W/rodir; for f in README.md results.json fig.png; do echo "b21 mine $f" > $W/mine/$f; done; echo "b21 a file" > $W/afile; md5sum $W/mine/* README.md $W/afile > ../m
tryf "(a) -noRun -output mine" paperFigures -noRun -output $W/mine; tryf "(b) -noRun -output ." paperFigures -noRun -output .; tryf "(c) -output a file" paperFigures -noRun -output $W/afile
ro $W/rodir; tryf "(d) -output under a read-only folder" paperFigures -noRun -output $W/rodir/out
echo "   files: $(md5sum -c ../m 2>&1 | awk '{print $2}' | sort | uniq -c | tr '\n' ' '); mine/: $(ls $W/mine | tr '\n' ' ')"
