#!/bin/bash
# CASETIMEOUT=900
# n01 (new, class 2/4: the output folders of the scripts the docs tell a user to run): a user's folder with their files
# (notes.txt, data/run1.csv) given as (or named inside) the output folder of: (a) tests/blast/runPreview.sh DIR (docs/
# benchmarks.md), (b) bench/blast/probeCost.sh OLDLIB DIR, (c) bench/blast/restLadder.sh preview DIR LABEL (DIR/LABEL the
# user's) and (d) quarter3D, (e) bench/blast/restVariants3D.sh DIR LABEL, (f) bench/blast/transparentCell.sh DIR 0.7 water
# (DIR and the user's DIR.log), (g) tutorials/indentation/gapStudy.sh averageCell NAME with WORK=the user's folder holding
# averageCell_NAME (an earlier study's kept case, "WORK keeps the case folders"), (h) meshConvergence.sh WORK=... 1.4,
# (i) bench/blast/planeWaveCellLadder.sh DIR (DIR/column the user's), (j) bench/blast/run.py --out DIR (DIR/level_1.4 the
# user's) and (k) bench/blast/quarter3D.py --out DIR (DIR/quarter3D_1.4). Each killed after 25 s if still going (its
# processes too). Never a user's file removed or replaced without an explicit option: refused naming the folder, or the
# files kept.
. "$(dirname "$0")/../lib.sh"
mk() { rm -rf "$1"; mkdir -p "$1/data"; echo "user's notes" > "$1/notes.txt"; echo "1,2" > "$1/data/run1.csv"; }
chk() { echo "   user's files in $(basename $(dirname $1))/$(basename $1): $(cd $1 2>/dev/null && ls notes.txt data/run1.csv 2>/dev/null | tr '\n' ' ' || echo 'FOLDER GONE') $( [ -f $1/notes.txt ] && [ "$(cat $1/notes.txt)" = "user's notes" ] || echo '(notes.txt gone or changed)')"; }
run() { local l=$1; shift; cd $W/here; tryt 25 "$l" "$@"; killIn $W; sleep 1; killIn $W; echo "   out: $(grep -av '^ *$' $W/try.log | head -3 | tr '\n' '|' | cut -c1-300)"; }
mkdir -p $W/here; B=$ROOT/bench/blast
mk $W/u; run "(a) tests/blast/runPreview.sh \$W/u -noRun" "$ROOT/tests/blast/runPreview.sh" $W/u -noRun; chk $W/u
mk $W/u; run "(b) bench/blast/probeCost.sh \$FOAM_USER_LIBBIN \$W/u" bash $B/probeCost.sh "$FOAM_USER_LIBBIN" $W/u; chk $W/u
mk $W/d/mine; run "(c) restLadder.sh preview \$W/d mine '-noRun'" bash $B/restLadder.sh preview $W/d mine "-endTime 1e-11"; chk $W/d/mine
mk $W/d/mine; run "(d) restLadder.sh quarter3D \$W/d mine '-endTime 1e-11'" bash $B/restLadder.sh quarter3D $W/d mine "-endTime 1e-11"; chk $W/d/mine
mk $W/d/mine; run "(e) restVariants3D.sh \$W/d mine '-endTime 1e-11' ''" bash $B/restVariants3D.sh $W/d mine "-endTime 1e-11" ""; chk $W/d/mine
mk $W/u; echo "user's log" > $W/u.log; run "(f) transparentCell.sh \$W/u 0.7 water" bash $B/transparentCell.sh $W/u 0.7 water; chk $W/u; echo "   \$W/u.log: $(head -1 $W/u.log | cut -c1-80)"
mk $W/wk/averageCell_mine; run "(g) WORK=\$W/wk gapStudy.sh averageCell mine" env WORK=$W/wk bash $ROOT/tutorials/indentation/gapStudy.sh averageCell mine; chk $W/wk/averageCell_mine
mk $W/wk/averageCell_1.4; run "(h) WORK=\$W/wk meshConvergence.sh 1.4" env WORK=$W/wk bash $ROOT/tutorials/indentation/meshConvergence.sh 1.4; chk $W/wk/averageCell_1.4
mk $W/pl/column; run "(i) planeWaveCellLadder.sh \$W/pl" bash $B/planeWaveCellLadder.sh $W/pl; chk $W/pl/column
mk $W/ro/level_1.4; run "(j) bench/blast/run.py --quick --out \$W/ro" /usr/bin/python3 $B/run.py --quick --out $W/ro; chk $W/ro/level_1.4
mk $W/qo/quarter3D_1.4; run "(k) bench/blast/quarter3D.py --quick --out \$W/qo" /usr/bin/python3 $B/quarter3D.py --quick --out $W/qo; chk $W/qo/quarter3D_1.4
