#!/bin/bash
# CASETIMEOUT=600
# l06 (new, class 4: numbers and spaces copied from a PDF, a web page or a European keyboard into a dictionary): the
# short preview (sb): (a) controlDict `endTime 2e-11;` with a no-break space (U+00A0) between key and value; (b) fsiProperties
# coupling tolerance `−1e-4` (U+2212 minus sign); (c) tolerance `1,5e-4` (decimal comma); (d) endTime `2e-11 s` (a unit);
# (e) solidProperties shearViscosity `0.2` written with a fullwidth digit `０.2`; (f) the indentation's radius `22,5e-6`;
# (g) cellMeshDict.allrun nucleusSize `0,5e-6` (quarter mesh folder, cellMesh). Expected: each refused naming the
# file, the entry and the odd character (or taken as meant, e.g. NBSP as a space); a value taken as something else
# without a word (1,5e-4 as 1, or 22,5e-6 as 22) = SILENT; an error that hides the character = UNCLEAR (low).
. "$(dirname "$0")/../lib.sh"
sb; cp -a . $W/b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
one() { tryt 150 "$1" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-330)"; back; }
sed -i 's/^endTime .*/endTime\xc2\xa02e-11;/' system/controlDict.allrun; grep -c $'\xc2\xa0' system/controlDict.allrun | sed 's/^/   NBSP lines: /'; one "(a) endTime<NBSP>2e-11"
sete constant/fsiProperties tolerance $'\xe2\x88\x921e-4'; one "(b) tolerance U+2212 1e-4"
sete constant/fsiProperties tolerance '1,5e-4'; one "(c) tolerance 1,5e-4"
sed -i 's/^endTime .*/endTime 2e-11 s;/' system/controlDict.allrun; one "(d) endTime 2e-11 s"
sete constant/solidProperties shearViscosity $'\xef\xbc\x90.2'; one "(e) shearViscosity fullwidth-0 .2"
cd $W; ind; sete constant/indenterProperties radius '22,5e-6'; tryt 150 "(f) indentation radius 22,5e-6" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-330)"
cd $W; qm; mset nucleusSize '0,5e-6'; cm; echo "   $(tail -1 $W/try.log | cut -c1-200)"
