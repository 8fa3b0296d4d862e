#!/bin/bash
# a02 (class 1, pulseStudy, k23's root in ANOTHER dictionary): the base case's system/fvSchemes takes its interpolationSchemes from an absolute path outside the base case ($W/sch/interp, #include); one point finished; reconstruct(p) MUSCL -> vanLeer in that file (k12 (b): a solver restart refuses this change); grid value 40e6 added; ./Allrun -keep: refused naming the changed file, or the new point run with the other scheme and nothing said?
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/sch; cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/base; f=$W/base/system/fvSchemes
sed -n '/^interpolationSchemes/,/^}/p' $f > $W/sch/interp; sed -i '/^interpolationSchemes/,/^}/d' $f; echo "#include \"$W/sch/interp\"" >> $f; echo "   fvSchemes: $(grep -a '#include' $f)"
study; sed -i "s|^baseCase .*|baseCase        \"$W/base\";|" system/pulseStudyDict; run 250 ./Allrun > ../log.s1 2>&1; echo "   first: $(grep -a -i -m3 'error\|done\|points' ../log.s1 | cut -c1-160 | tr '\n' '|')"
sed -i 's/^\( *reconstruct(p) *\)MUSCL;/\1vanLeer;/' $W/sch/interp; echo "   changed: $(grep -a 'reconstruct(p)' $W/sch/interp | tr -s ' ')"
setStudy overpressure "(30e6 40e6)"; run 250 ./Allrun -keep > ../log.s2 2>&1; echo "   again: $(grep -a -i -m5 'error\|refus\|differ\|changed\|done\|not run' ../log.s2 | cut -c1-220 | tr '\n' '|')"
echo "   points: $(ls postProcessing/pulseStudy/points | tr '\n' ' '); table rows: $(tail -n +2 postProcessing/pulseStudy/table.csv 2>/dev/null | grep -vc '^#')"
