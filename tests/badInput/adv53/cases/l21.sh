#!/bin/bash
# CASETIMEOUT=600
# l21 (new, class 4: a misspelt or unknown keyword - and a key glued to its value by a no-break space - in the
# dictionaries' *.allrun files, which the dictionaries #sinclude at their end; users write there too - fix19i keeps a
# user's own DICT.allrun): the short preview sb (endTime 2e-11, writeInterval 1e-11 in controlDict.allrun) with
# (a) controlDict.allrun `writeInteval 5e-12;` (typo) added, (b) controlDict.allrun `foo 3;`, (c) controlDict.allrun
# `writeInterval<NBSP>5e-12;` (replacing its writeInterval line: the run then takes controlDict's own), (d)
# constant/fsiProperties.allrun `coupling { tolerence 5e-5; }`, (e) constant/solidProperties.allrun `shearViscosty 0.1;`,
# (f) the quarter's mesh folder: system/cellMeshDict.allrun `nucleusSise 0.4e-6;` (cellMesh); (g) control: `foo 3;` in
# controlDict itself. Expected: each refused naming the file, the line and the closest valid keyword (the project's
# keyword check, as for the dictionaries themselves: (g)); accepted with the entry ignored rc 0 = SILENT. Added: (h) the
# same typos in a file controlDict #includes (system/myControl), (i) a typo in a file fsiProperties' coupling{} #includes.
. "$(dirname "$0")/../lib.sh"
sb; cp -a . $W/b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
one() { tryt 150 "$1" "${@:2}"; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-260) | times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"; }
echo 'writeInteval 5e-12;' >> system/controlDict.allrun; one "(a) controlDict.allrun: writeInteval 5e-12 (typo)" cellBlastFoam; back
echo 'foo 3;' >> system/controlDict.allrun; one "(b) controlDict.allrun: foo 3" cellBlastFoam; back
sed -i 's/^writeInterval .*/writeInterval\xc2\xa05e-12;/' system/controlDict.allrun; one "(c) controlDict.allrun: writeInterval<NBSP>5e-12" cellBlastFoam; back
printf '// Written by Allrun from its options (removed by Allclean)\ncoupling { tolerence 5e-5; }\n' > constant/fsiProperties.allrun; grep -q 'fsiProperties.allrun' constant/fsiProperties || printf '\n#sinclude "fsiProperties.allrun"\n' >> constant/fsiProperties; one "(d) fsiProperties.allrun: coupling { tolerence 5e-5; }" cellBlastFoam; back
printf '// Written by Allrun from its options (removed by Allclean)\nshearViscosty 0.1;\n' > constant/solidProperties.allrun; grep -q 'solidProperties.allrun' constant/solidProperties || printf '\n#sinclude "solidProperties.allrun"\n' >> constant/solidProperties; one "(e) solidProperties.allrun: shearViscosty 0.1" cellBlastFoam; back
sed -i 's/^endTime/foo 3;\nendTime/' system/controlDict; one "(g) control: foo 3 in controlDict itself" cellBlastFoam; back
printf 'writeInteval 5e-12;\nmaxCO 0.1;\n' > system/myControl; sed -i 's|^endTime|#include "myControl"\nendTime|' system/controlDict; one "(h) controlDict: #include \"myControl\" (writeInteval 5e-12; maxCO 0.1;)" cellBlastFoam; back
printf 'tolerence 5e-5;\n' > constant/myCoupling; /usr/bin/python3 - constant/fsiProperties <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read(); m = re.search(r'^coupling\s*\{', t, re.M); open(p, 'w').write(t[:m.end()] + '\n    #include "myCoupling"' + t[m.end():])
P
one "(i) fsiProperties coupling{ #include \"myCoupling\" (tolerence 5e-5;) }" cellBlastFoam; back
cd $W; ind; printf 'checkpointIntreval 3;\n' > system/myControl; echo '#include "myControl"' >> system/controlDict; one "(j) the indentation's controlDict #include (checkpointIntreval 3;)" cellIndentationFoam
cd $W; wp 1e-9; rm -rf [1-9]* postProcessing; printf 'writeInteval 1e-9;\n' > system/myControl; sed -i 's|^endTime|#include "myControl"\nendTime|' system/controlDict; one "(k) waterPulseWall's controlDict #include (writeInteval 1e-9;)" rhoRiemannFoam
cd $W; qm; echo 'nucleusSise 0.4e-6;' >> system/cellMeshDict.allrun; cm; echo "   $(grep -a -i -m1 'unknown\|nucleusSise' $W/try.log | cut -c1-200)"
