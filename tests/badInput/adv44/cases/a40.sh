#!/bin/bash
# a40 (class 1, pulseStudy, the CONTROL of a01/a38/a39: an outside include changed without changing what it says): a01's setting ($ADV44MAT/set outside the base case); one point finished; the set's file then (a) only touched, (b) given a comment line, (c) the membrane's C10 respelled (166.67 -> 1.6667e2); a grid value added each time; ./Allrun: the new points run and nothing refused (the inputs are the same), or refused as a change (a false alarm)?
. "$(dirname "$0")/../lib.sh"
export ADV44MAT=$W/mat; mkdir -p $ADV44MAT; cp "$ROOT/etc/caseDicts/cellMaterials/textFactor4" $ADV44MAT/set; cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/base
sed -i 's|#include "$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4"|#include "$ADV44MAT/set"|' $W/base/constant/solidProperties
study; sed -i "s|^baseCase .*|baseCase        \"$W/base\";|" system/pulseStudyDict; run 250 ./Allrun > ../log.s1 2>&1; echo "   first: $(grep -a -i -m3 'error\|done' ../log.s1 | cut -c1-160 | tr '\n' '|')"
g="30e6"; for k in touch comment respell; do case $k in touch) sleep 1; touch $ADV44MAT/set;; comment) echo "// a40 my comment" >> $ADV44MAT/set;; respell) sed -i '0,/166.67/s//1.6667e2/' $ADV44MAT/set;; esac
  g="$g 3${#g}e6"; setStudy overpressure "($g)"; run 250 ./Allrun > ../log.$k 2>&1; echo "   ($k) grid ($g): $(grep -a -i -m3 'error\|refus\|differ\|done' ../log.$k | cut -c1-200 | tr '\n' '|')"; done
