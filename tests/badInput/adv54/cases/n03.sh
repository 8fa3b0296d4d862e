#!/bin/bash
# CASETIMEOUT=900
# n03 (new, class 5: a result copied to another case with its digests): (a) two finished smoke indentations, A (idn) and B
# (the same with the material set 'table' instead of 'textFactor4' included in constant/solidProperties, run to its end):
# A's force.dat, peaks.dat and their sidecars copied into B's postProcessing/indentation/ (a user copying "the results"
# between case folders); plotIndentation.py B. (b) p8's postProcessing/planeWave/0/reference.dat (+ sidecar; pulse 50 MPa)
# copied into q8 (the same preview to 8 ns with the pulse doubled): incidentWindow.py q8, and planeWave -check -reference
# <p8's> in q8; (c) p8's fluidProbes/0/p copied into q8: planeWave -check. Expected: refused naming the copy as another
# run's (the run id in peaks.dat's header; the pulse in reference.dat's header against the case's) - A's table printed as
# B's, or q8 measured against p8's 50 MPa wave without a word = SILENT.
. "$(dirname "$0")/../lib.sh"
idn; A=$PWD; cd $W; mkdir B; cp -r $A/system $A/constant B/; cd B
sed -i 's|cellMaterials/textFactor4|cellMaterials/table|' constant/solidProperties; grep -n '^ *#include' constant/solidProperties | head -2
tryt 300 "B runs" cellIndentationFoam; pi; echo "   B as written: $(pk) | run ids A $(head -n 1 $A/postProcessing/indentation/peaks.dat) B $(head -n 1 postProcessing/indentation/peaks.dat)"
cp $A/postProcessing/indentation/{force.dat,force.dat.fnv1a64,peaks.dat,peaks.dat.fnv1a64} postProcessing/indentation/; pi; echo "   (a) B with A's results copied in: $(pk)"
cd $W; p8; P=$PWD; grep -a -m3 'peak1ns\|^fluid\|^ *fluidProbes' log.planeWave | cut -c1-200; cd $W; q8; tryt 300 "(0) planeWave in q8 (its own reference)" planeWave -case .; grep -a -A3 '^# probe' $W/try.log | head -4 | cut -c1-200; cp -a postProcessing $W/q8pp
cp $P/postProcessing/planeWave/0/reference.dat* postProcessing/planeWave/0/; head -c 150 postProcessing/planeWave/0/reference.dat; echo
iw .; echo "   (b) incidentWindow q8 with p8's reference: $(grep -a -v '^ *$' $W/try.log | tail -n 3 | tr '\n' '|' | cut -c1-500)"
rm -rf postProcessing; cp -a $W/q8pp postProcessing; tryt 300 "(b2) planeWave -check -reference p8's in q8" planeWave -case . -check -reference $P/postProcessing/planeWave/0/reference.dat; grep -a -A3 '^# probe' $W/try.log | head -4 | cut -c1-200
cp $P/postProcessing/fluidProbes/0/p postProcessing/fluidProbes/0/p; tryt 300 "(c) p8's probe log in q8: planeWave -check" planeWave -case . -check
