#!/bin/bash
# CASETIMEOUT=600
# l30 (new, class 4: adv52 o07's duplicate across an #include, in every dictionary our checks read - fix19j item 5 asks
# for the class): a keyword given in the dictionary and again in a file it #includes (later wins in OpenFOAM):
# (a) sb: constant/solidProperties shearViscosity (again 0.1 in an included file), (b) sb: constant/fsiProperties
# coupling{} tolerance (o07), (c) sb: system/controlDict maxCo (again 0.5 in an included file), (d) ind:
# constant/indenterProperties radius (again 30e-6 in an included file), (e) wp: constant/thermophysicalProperties
# mieGruneisenCoeffs Gamma0 (again in an included file), (f) qm: cellMeshDict.allrun nucleusSize (again; the control:
# adv52 saw cellMeshDict refuse). Expected: each refused naming both places (the project's rule: a keyword given twice is
# an error); taken silently = UNCLEAR (o07's class; SILENT if the later value changes the run).
. "$(dirname "$0")/../lib.sh"
one() { tryt 150 "$1" "${@:2}"; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-260)"; }
incl() { /usr/bin/python3 - "$1" "$2" "$3" "$4" <<'P'
import re, sys, os
p, sec, inc, text = sys.argv[1:5]; t = open(p).read()
open(os.path.join(os.path.dirname(p), inc), 'w').write(text + '\n')
if sec == '-':
    m = re.search(r'^FoamFile\s*\{.*?\n\}', t, re.S | re.M); k = m.end() if m else 0
    t = t[:k] + '\n#include "%s"\n' % inc + t[k:]
else:
    m = re.search(r'^\s*%s\s*\{' % sec, t, re.M); t = t[:m.end()] + '\n    #include "%s"' % inc + t[m.end():]
open(p, 'w').write(t)
P
}
sb; cp -a . $W/b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
incl constant/solidProperties - solidUser 'shearViscosity 0.1;'; one "(a) solidProperties: shearViscosity in solidUser (included first) and in the file" cellBlastFoam; back
incl constant/fsiProperties coupling couplingUser 'tolerance 5e-5;'; one "(b) fsiProperties coupling{}: tolerance in couplingUser and in the file" cellBlastFoam; back
incl system/controlDict - controlUser 'maxCo 0.5;'; one "(c) controlDict: maxCo in controlUser and in the file" cellBlastFoam; back
cd $W; ind; incl constant/indenterProperties - indUser 'radius 30e-6;'; one "(d) indenterProperties: radius in indUser and in the file" cellIndentationFoam
cd $W; wp 1e-9; rm -rf [1-9]* postProcessing; incl constant/thermophysicalProperties mieGruneisenCoeffs eosUser 'Gamma0 0.2;'; one "(e) thermophysicalProperties mieGruneisenCoeffs{}: Gamma0 in eosUser and in the file" rhoRiemannFoam
cd $W; qm; printf 'nucleusSize 0.6e-6;\n' > system/meshUser; sed -i '1i #include "meshUser"' system/cellMeshDict.allrun; cm; echo "   $(grep -a -i -m1 'twice\|given' $W/try.log | cut -c1-220)"
