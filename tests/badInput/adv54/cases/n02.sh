#!/bin/bash
# CASETIMEOUT=600
# n02 (new, class 5: a row appended to a finished blast's probe log and to planeWave's reference.dat): pw (the finished
# preview with planeWave's reference): (a) postProcessing/fluidProbes/0/p + one row at 2.05e-9 s
# (after the run's last row 2e-9) with p = 5e8 Pa; planeWave -case . -check, incidentWindow.py, plotBlast.py;
# (b) postProcessing/planeWave/0/reference.dat + one row (a later time, p x10);
# incidentWindow.py and planeWave -reference <it>. Expected: each refused naming the file and the row after the run's
# last commit (the run is finished); the row measured without a word = SILENT.
. "$(dirname "$0")/../lib.sh"
pwd0; cp -a . $W/p0; f=postProcessing/fluidProbes/0/p
tryt 300 "(0) planeWave -check, as written" planeWave -case . -check; grep -a 'peak\|plateau' $W/try.log | head -3 | cut -c1-200
iw .; echo "   (0) incidentWindow: $(grep -a -v '^ *$' $W/try.log | tail -n 2 | tr '\n' '|' | cut -c1-300)"
printf '  2.0500000000000001e-09   5.0000000000000000e+08\n' >> $f; ok_ $f
tryt 300 "(a) planeWave -check, p + a row after the run's end" planeWave -case . -check; grep -a 'peak\|plateau\|partial\|not\|after' $W/try.log | head -4 | cut -c1-200
iw .; echo "   (a) incidentWindow: $(grep -a -v '^ *$' $W/try.log | tail -n 2 | tr '\n' '|' | cut -c1-300)"
tryt 300 "(a) plotBlast.py ." /usr/bin/python3 $ROOT/tutorials/blast/plotBlast.py .; echo "   (a) plotBlast: $(grep -a -i 'peak\|MPa\|error' $W/try.log | head -3 | tr '\n' '|' | cut -c1-300)"
cd $W; rm -rf pw; cp -a p0 pw; cd pw; r=postProcessing/planeWave/0/reference.dat; tail -n 1 $r | awk '{ $1 = $1 + 1e-9; for (i = 2; i <= 3; i++) $i = $i * 10 + 5e8; print }' >> $r; ok_ $r
iw .; echo "   (b) incidentWindow on reference.dat + a row: $(grep -a -v '^ *$' $W/try.log | tail -n 2 | tr '\n' '|' | cut -c1-300)"
cp $r $W/ref.dat; cp $r.fnv1a64 $W/ref.dat.fnv1a64; tryt 300 "(b) planeWave -reference (the appended one, with its sidecar)" planeWave -case . -reference $W/ref.dat
tryt 300 "(b) planeWave -reference, in the case" planeWave -case . -check -reference $r; grep -a 'peak\|plateau' $W/try.log | head -2 | cut -c1-200
