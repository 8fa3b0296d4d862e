#!/bin/bash
# CASETIMEOUT=600
# o07 (fix19h's file and line of a sub-dictionary's entry, adv51 m02/m10, varied: entries given through #include'd files,
# macros and #includeEtc-less copies): the short preview (sb, endTime 2e-11): constant/fsiProperties' coupling{}:
# (a) `#include "couplingUser"` (constant/couplingUser, line 3: tolerance 0.5;), (b) a macro: `tolUser 0.5;` at the top
# level and `tolerance $tolUser;` in coupling{}, (c) interface{} motionNearest 0 in an included file of a sub-folder
# (constant/inc/iface); the quarter's mesh folder (qm): (d) fluid{} nearSize 1e-3 given by `#include "fluidUser"` inside
# fluid{} of cellMeshDict.allrun; (e) solidProperties' probes radius -1 through an #include. Each: refused rc 1 naming,
# in "file:", the file and line where the value is written (couplingUser line 3; the macro's line or the use's; ...),
# the entry and its range; a file that does not exist or the wrong line = UNCLEAR.
. "$(dirname "$0")/../lib.sh"
res() { echo "   file: $(grep -a -m2 -o 'file: [^ ]* *[^ ]* *[^ ]* *[^ ]* *[^ ]*' $W/try.log | tr '\n' '|') | entry: $(grep -a -m1 -o "entry '[^']*'[^.]*" $W/try.log | cut -c1-200)"; }
sb; cp -a . $W/b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
ins() { /usr/bin/python3 - constant/fsiProperties "$1" "$2" <<'P'
import re, sys
p, sec, text = sys.argv[1:4]; t = open(p).read(); m = re.search(r'^%s\s*\{' % sec, t, re.M)
open(p, 'w').write(t[:m.end()] + '\n    ' + text + t[m.end():])
P
}
printf '// a user file of coupling settings\n\ntolerance 0.5;\n' > constant/couplingUser; ins coupling '#include "couplingUser"'
tryt 120 "(a) coupling tolerance 0.5 from #include couplingUser line 3" cellBlastFoam; res; back
sed -i '/^interface/i tolUser 0.5;' constant/fsiProperties; ins coupling 'tolerance $tolUser;'; echo "   macro at line $(grep -n '^tolUser' constant/fsiProperties | cut -d: -f1), use at line $(grep -n 'tolerance \$tolUser' constant/fsiProperties | cut -d: -f1)"
tryt 120 "(b) coupling tolerance \$tolUser (0.5)" cellBlastFoam; res; back
mkdir -p constant/inc; printf 'motionNearest 0;\n' > constant/inc/iface; ins interface '#include "inc/iface"'
tryt 120 "(c) interface motionNearest 0 from constant/inc/iface line 1" cellBlastFoam; res; back
tryt 120 "(e0) control: solidProperties probes" true; grep -n "probes\|radius" constant/solidProperties | head -5 | sed 's/^/   solidProperties: /'
if grep -q "radius" constant/solidProperties; then ln=$(grep -n "radius" constant/solidProperties | head -1 | cut -d: -f1); printf '\nradius -1;\n' > constant/probeUser; sed -i "${ln}s/radius[^;]*;/#include \"probeUser\"/" constant/solidProperties
  tryt 120 "(e) solidProperties probes radius -1 from #include probeUser line 2" cellBlastFoam; res; back; fi
cd $W; rm -rf blast b0; qm; printf '\nnearSize 1e-3;\n' > system/fluidUser; sed -i 's/nearSize 1e-6;/#include "fluidUser"/' system/cellMeshDict.allrun; tail -1 system/cellMeshDict.allrun | cut -c1-150 | sed 's/^/   allrun: /'
tryt 300 "(d) cellMesh: fluid{} nearSize 1e-3 from #include fluidUser line 2" cellMesh; res
