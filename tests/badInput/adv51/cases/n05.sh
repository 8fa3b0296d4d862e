#!/bin/bash
# CASETIMEOUT=600
# n05 (new, class 4/5: the tutorials' own plot and mesh scripts, which their Allruns run and a user re-runs by hand; the
# corpus has 0-4 cases each): (a) indentation/plotIndentation.py on the finished smoke indentation (control), on the
# killed one (ik: a partial force.dat), with force.dat emptied, cut mid-line, a nan row, on a folder that is no case, on
# a missing folder; (b) indentation/plotFields.py on the smoke case with the labels C1,i (default), X9 (not in peaks.dat),
# '' and on the killed case; without an argument; (c) blast/plotBlast.py on the finished preview (control), with
# solid.h5 missing, coupling.dat emptied, on a missing folder; (d) blast/fluidWedgeMesh.py -h nan, -far -0, -Z 1e400,
# -wedge 0, -maxCells 1.5, -o a directory. Each: a plot written, or one line naming what is wrong, rc != 0; never a
# traceback; never a file of the case other than the plot changed.
. "$(dirname "$0")/../lib.sh"
tb() { echo "   traceback: $(grep -a -c '^Traceback' $W/try.log) | last: $(grep -av '^ *$' $W/try.log | tail -2 | tr '\n' ' ' | cut -c1-300) | png: $(ls -t *.png 2>/dev/null | head -2 | tr '\n' ' ')"; }
T=$ROOT/tutorials; PI="/usr/bin/python3 $T/indentation/plotIndentation.py"; PF="/usr/bin/python3 $T/indentation/plotFields.py"; PB="/usr/bin/python3 $T/blast/plotBlast.py"
idn; I=$PWD; cp -a . ../i0; bi() { cd $W; rm -rf ind; cp -a i0 ind; cd ind; }
F=postProcessing/indentation/force.dat
tryt 120 "(a) plotIndentation.py . (finished smoke)" $PI .; tb
bi; : > $F; tryt 120 "(a) force.dat emptied" $PI .; tb
bi; head -c $(( $(stat -c %s $F) * 2 / 3 )) $F > $W/f; cp $W/f $F; tryt 120 "(a) force.dat cut mid-line" $PI .; tb
bi; sed -i "$(( $(wc -l < $F) / 2 ))s/[-0-9.e+]*\$/nan/" $F; tryt 120 "(a) force.dat with a nan" $PI .; tb
bi; tryt 60 "(a) on a folder that is no case (\$W)" $PI $W; tb; tryt 60 "(a) on a missing folder" $PI $W/nosuch; tb
bi; tryt 200 "(b) plotFields.py . (C1,i)" $PF .; tb
for l in X9 ""; do bi; tryt 120 "(b) plotFields.py . '$l'" $PF . "$l"; tb; done
bi; tryt 60 "(b) plotFields.py without an argument" $PF; tb
cd $W; rm -rf ind i0; ik; tryt 120 "(a) plotIndentation.py on the killed run (partial force.dat)" $PI .; tb; tryt 120 "(b) plotFields.py on the killed run" $PF .; tb
cd $W; rm -rf ind; bd; cp -a . ../b0; bb() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
tryt 200 "(c) plotBlast.py . (finished preview)" $PB .; tb
bb; rm -f solid/solid.h5; tryt 200 "(c) solid.h5 missing" $PB .; tb
bb; : > $(find postProcessing -name coupling.dat | head -1); tryt 200 "(c) coupling.dat emptied" $PB .; tb
tryt 60 "(c) a missing folder" $PB $W/nosuch; tb
cd $W; mkdir -p fw/system; cd fw; FW="/usr/bin/python3 $T/blast/fluidWedgeMesh.py"
for o in "-h nan" "-far -0" "-Z 1e400" "-wedge 0" "-maxCells 1.5" "-o system"; do tryt 60 "(d) fluidWedgeMesh.py $o" $FW $o; tb; done
