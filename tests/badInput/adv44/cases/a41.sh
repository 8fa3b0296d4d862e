#!/bin/bash
# a41 (class 2, pulseStudy's reading of the base case's dictionaries with their #calc expanded): the base case (a tutorial copy) holds the user's own dynamicCode/ folder (notes.txt, a file of theirs) and its constant/solidProperties a `#calc` (shearViscosity #calc "0.1 + 0.1";); one point; the base case's dynamicCode/ and its files kept, nothing written into the base case? (then ./Allrun again: nothing to run)
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/base; mkdir -p $W/base/dynamicCode/mine; echo "a41 my dynamicCode notes" > $W/base/dynamicCode/notes.txt; echo "a41 my code" > $W/base/dynamicCode/mine/code.C
sed -i 's|^shearViscosity .*|shearViscosity  #calc "0.1 + 0.1";|' $W/base/constant/solidProperties; grep -a '^shearViscosity' $W/base/constant/solidProperties; (cd $W/base && find . -type f | sort | xargs md5sum) > $W/b0
study; sed -i "s|^baseCase .*|baseCase        \"$W/base\";|" system/pulseStudyDict; run 250 ./Allrun > ../log.s1 2>&1; echo "   first: $(grep -a -i -m3 'error\|done\|FAIL' ../log.s1 | cut -c1-200 | tr '\n' '|')"
run 250 ./Allrun > ../log.s2 2>&1; echo "   again: $(grep -a -i -m3 'error\|refus\|not run\|done' ../log.s2 | cut -c1-200 | tr '\n' '|')"
where "a41 my dynamicCode notes" "a41 my code"; echo "   the base case changed: $(cd $W/base && find . -type f | sort | xargs md5sum | diff $W/b0 - | grep '^[<>]' | awk '{print $1, $3}' | tr '\n' ' ')"
