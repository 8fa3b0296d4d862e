#!/bin/bash
# CASETIMEOUT=600
# l13 (new, class 4: a dictionary that includes itself - a copy-paste of an #include line into the included file -
# and a macro that names itself): the short preview (sb): (a) constant/fsiProperties with `#include "fsiProperties"`
# (itself) inside coupling{}; (b) two files including each other (constant/fsiProperties -> constant/couplingA ->
# constant/fsiProperties); (c) a macro `tol $tol;` used as `tolerance $tol;`; (d) system/cellMeshDict including itself
# (cellMesh, qm); (e) constant/indenterProperties including itself (ind). Expected: refused naming the file and the
# cycle (rc != 0) within seconds; a SIGSEGV (stack overflow) = CRASH; no end at 60 s = HANG.
. "$(dirname "$0")/../lib.sh"
one() { tryt 60 "$1" "${@:2}"; echo "   sig/stack lines $(sig) | Segm: $(grep -a -c -i 'segmentation\|SIGSEGV' $W/try.log) | said: $(say 2 | cut -c1-250) | last: $(tail -1 $W/try.log | cut -c1-120)"; }
ins() { /usr/bin/python3 - "$1" "$2" "$3" <<'P'
import re, sys
p, sec, text = sys.argv[1:4]; t = open(p).read(); m = re.search(r'^%s\s*\{' % sec, t, re.M)
open(p, 'w').write(t[:m.end()] + '\n    ' + text + t[m.end():])
P
}
sb; cp -a . $W/b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
ins constant/fsiProperties coupling '#include "fsiProperties"'; one "(a) fsiProperties includes itself" cellBlastFoam; back
ins constant/fsiProperties coupling '#include "couplingA"'; printf '#include "fsiProperties"\n' > constant/couplingA; one "(b) fsiProperties <-> couplingA" cellBlastFoam; back
sed -i 's|^coupling|tol $tol;\n\ncoupling|' constant/fsiProperties; sete constant/fsiProperties tolerance '$tol'; one "(c) tol \$tol; tolerance \$tol;" cellBlastFoam; back
cd $W; qm; echo '#include "cellMeshDict"' >> system/cellMeshDict; one "(d) cellMeshDict includes itself" cellMesh
cd $W; ind; echo '#include "indenterProperties"' >> constant/indenterProperties; one "(e) indenterProperties includes itself" cellIndentationFoam
