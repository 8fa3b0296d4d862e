#!/bin/bash
# CASETIMEOUT=600
# l20 (new, class 2: the Allrun's own record of its options, .allrunOptions, removed or edited by a user's clean-up -
# the record is what refuses an Allrun with other options in a finished case, adv52 p12): the finished preview A
# (runPreview.sh, run to 2e-9) with (a) .allrunOptions removed, then ./Allrun -noRun with another -cell; (b)
# .allrunOptions edited to the new options by hand; (c) .allrunOptions made empty. Expected: refused naming the results
# (time directories, solid/) that new meshes would leave behind; the meshes replaced under the results rc 0 = DATALOSS
# (a later restart on other meshes).
. "$(dirname "$0")/../lib.sh"
O="-h 0.5e-6 -far 4e-6 -dz 0.5e-6 -Z 20e-6 -endTime 2e-9 -noPlots -noVTK"
cd $W; tryt 600 "(0) runPreview.sh A -cell 1e-6 (run to 2e-9)" bash $ROOT/tests/blast/runPreview.sh $W/A $O -cell 1e-6; cd $W/A/axisymmetricPreview; echo "   times: $(ls -d [0-9]* | tr '\n' ' ') | .allrunOptions: $(head -c 200 .allrunOptions 2>/dev/null | tr '\n' ' ')"
cd $W; cp -a A A0; back() { cd $W; rm -rf A; cp -a A0 A; cd A/axisymmetricPreview; }
one() { sums > $W/s0; tryt 400 "$1" ./Allrun $O -cell 1.2e-6 -noRun; echo "   said: $(grep -a -i -m2 'error\|refus' $W/try.log | tr '\n' '|' | cut -c1-300) | changed: $(changed $W/s0 | cut -c1-200) | meshes $(md5sum constant/cell.msh | cut -c1-8)"; }
back; rm -f .allrunOptions; one "(a) .allrunOptions removed, Allrun -cell 1.2e-6 -noRun"
back; sed -i 's/1e-6/1.2e-6/g' .allrunOptions 2>/dev/null; one "(b) .allrunOptions edited to -cell 1.2e-6"
back; : > .allrunOptions; one "(c) .allrunOptions emptied"
