#!/bin/bash
# CASETIMEOUT=600
# o09 (fix19h's output-folder rule, adv51 n01, varied: marked folders, names, the scripts it did not change): a user's
# notes at the output paths of: (a) tests/blast/runPreview.sh DIR where DIR carries the marker of runPreview.sh (copied
# from an earlier output) beside the user's notes.txt; (b) the same with the user's file inside the script's own entry
# (DIR/axisymmetricPreview/mine.txt, marker present); (c) DIR/ (trailing slash) of a user's folder; (d) bench/blast/run.py
# --quick --out DIR with DIR/level_1.4 marked by an earlier run.py and holding the user's analysis.txt (run.py gives no
# entries: anything goes); (e) the marker naming "run.py" written by bench/blast/run.py, then bench/fluid/run.py --quick
# --out over the same folder's cost/ (another script of the same name); documented as unchanged (fix19h's NOT covered):
# (f) bench/fsi/pulseLayerMotion.sh OUT (OUT/laplacian.mesh/notes.txt), (g) bench/solid/structuredLadderRuns.sh OUT
# 0.35e-6 (OUT/mesh-structured-0.35e-6/notes.txt), (h) bench/fluid/memoryPerCell.py --out DIR (DIR/box40/notes.txt),
# (i) bench/fluid/run.py --quick --out DIR (DIR/cost/1D_HLLC/notes.txt). Each script stopped after 25 s at most (only
# whether it removed the user's file matters): the user's file kept, or the loss said = DATALOSS.
. "$(dirname "$0")/../lib.sh"
B=$ROOT/bench; U=$W/u
run() { local l=$1; shift; tryt 25 "$l" "$@"; echo "   said: $(grep -a -m2 -i 'error\|refus\|exists' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-300)"; killAll $W; }
rm -rf $U; mkdir -p $U/d; echo runPreview.sh > $U/d/.scratchFolder; cd $U/d; mark notes.txt; cd $W
run "(a) runPreview.sh DIR: the marker of runPreview.sh beside notes.txt" bash $ROOT/tests/blast/runPreview.sh $U/d -noRun; cd $U/d; kept_ notes.txt; cd $W
rm -rf $U; mkdir -p $U/d/axisymmetricPreview; echo runPreview.sh > $U/d/.scratchFolder; cd $U/d; mark axisymmetricPreview/mine.txt; cd $W
run "(b) runPreview.sh DIR: marked, the user's file inside its entry axisymmetricPreview/" bash $ROOT/tests/blast/runPreview.sh $U/d -noRun; cd $U/d; kept_ axisymmetricPreview/mine.txt; cd $W
rm -rf $U; mkdir -p $U/d; cd $U/d; mark notes.txt; cd $W
run "(c) runPreview.sh DIR/ (trailing slash), a user's folder" bash $ROOT/tests/blast/runPreview.sh $U/d/ -noRun; cd $U/d; kept_ notes.txt; cd $W
rm -rf $U; mkdir -p $U/d/level_1.4; echo run.py > $U/d/level_1.4/.scratchFolder; cd $U/d; mark level_1.4/analysis.txt; cd $W
run "(d) bench/blast/run.py --quick --out DIR, DIR/level_1.4 marked by run.py with the user's analysis.txt" /usr/bin/python3 $B/blast/run.py --quick --out $U/d; cd $U/d; kept_ level_1.4/analysis.txt; cd $W
rm -rf $U; mkdir -p $U/d/cost/1D_HLLC; echo run.py > $U/d/cost/1D_HLLC/.scratchFolder; cd $U/d; mark cost/1D_HLLC/notes.txt; cd $W
run "(e/i) bench/fluid/run.py --quick --out DIR (DIR/cost/1D_HLLC/notes.txt, marked run.py)" /usr/bin/python3 $B/fluid/run.py --quick --parts 1 --out $U/d; cd $U/d; kept_ cost/1D_HLLC/notes.txt; echo "   DIR/cost now: $(ls $U/d/cost 2>/dev/null | tr '\n' ' ')"; cd $W
rm -rf $U; mkdir -p $U/d; cd $U/d; mark laplacian.mesh/notes.txt; cd $W
run "(f) bench/fsi/pulseLayerMotion.sh OUT (OUT/laplacian.mesh/notes.txt)" bash $B/fsi/pulseLayerMotion.sh $U/d 1; cd $U/d; kept_ laplacian.mesh/notes.txt; cd $W
rm -rf $U; mkdir -p $U/d; cd $U/d; mark mesh-structured-0.35e-6/notes.txt; cd $W
run "(g) bench/solid/structuredLadderRuns.sh OUT 0.35e-6 (OUT/mesh-structured-0.35e-6/notes.txt)" bash $B/solid/structuredLadderRuns.sh $U/d 0.35e-6; cd $U/d; kept_ mesh-structured-0.35e-6/notes.txt; cd $W
rm -rf $U; mkdir -p $U/d; cd $U/d; mark box40/notes.txt; cd $W
run "(h) bench/fluid/memoryPerCell.py --out DIR (DIR/box40/notes.txt)" /usr/bin/python3 $B/fluid/memoryPerCell.py --out $U/d --sizes 40 --steps 1; cd $U/d; kept_ box40/notes.txt; cd $W
