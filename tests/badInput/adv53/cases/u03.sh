#!/bin/bash
# CASETIMEOUT=600
# u03 (fix19i row "numbers in messages as given" (numberText), varied: entries of other readers than the 21 corpus rows, in
# cases whose writePrecision is 17): the short preview (sb) with (a) solidProperties explicitSafety 1.1, (b) shearViscosity
# -0.3, (c) interfaceProbe heightFraction 1.1, (d) fsiProperties coupling tolerance 0.3, (e) controlDict maxCo 1.1e3,
# (f) maxDeltaT -0.7e-9, (g) a material value C10 -0.1 of nucleus (after the #include); the smoke indentation (ind, its
# controlDict writePrecision set to 17) with (h) indenterProperties radius -0.1e-6, (i) tolerance 0.3e-9 -> -0.3e-9. Expected:
# each refused naming the entry with the number as given (1.1, -0.3, 0.3, 1100, -7e-10, -0.1, -1e-07, -3e-10); a number
# printed with 17 digits (1.1000000000000001, 0.29999999999999999, ...) = UNCLEAR (low).
. "$(dirname "$0")/../lib.sh"
n17() { local l; l=$(grep -a -o -E '[-+]?[0-9]\.[0-9]{12,}(e[-+]?[0-9]+)?' $W/try.log | sort -u | head -4 | tr '\n' ' '); echo "   17-digit numbers in the output: ${l:-none}"; }
sb; cp -a . $W/b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
one() { tryt 150 "$1" cellBlastFoam; echo "   said: $(say 3 | cut -c1-300)"; n17; back; }
sete constant/solidProperties explicitSafety 1.1; one "(a) explicitSafety 1.1"
sete constant/solidProperties shearViscosity -0.3; one "(b) shearViscosity -0.3"
sete constant/solidProperties heightFraction 1.1; one "(c) heightFraction 1.1"
sete constant/fsiProperties tolerance 0.3; one "(d) coupling tolerance 0.3"
sete system/controlDict maxCo 1.1e3; one "(e) maxCo 1.1e3"
sete system/controlDict maxDeltaT -0.7e-9 || echo 'maxDeltaT -0.7e-9;' >> system/controlDict; one "(f) maxDeltaT -0.7e-9"
/usr/bin/python3 - constant/solidProperties <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read(); i = t.index('nucleus', t.index('materials')); j = t.index('{', i) + 1
open(p, 'w').write(t[:j] + '\n        C10 -0.1;' + t[j:]); print('   nucleus C10 -0.1 added after the #include')
P
one "(g) nucleus C10 -0.1"
cd $W; ind; cp -a . $W/i0; sete system/controlDict writePrecision 17 || echo 'writePrecision 17;' >> system/controlDict; grep -n writePrecision system/controlDict | sed 's/^/   /'; cp -a . $W/i0
sete constant/indenterProperties radius -0.1e-6; tryt 150 "(h) indentation radius -0.1e-6" cellIndentationFoam; echo "   said: $(say 3 | cut -c1-300)"; n17
cd $W; rm -rf ind; cp -a i0 ind; cd ind; sete constant/indenterProperties tolerance -0.3e-9; tryt 150 "(i) indentation tolerance -0.3e-9" cellIndentationFoam; echo "   said: $(say 3 | cut -c1-300)"; n17
