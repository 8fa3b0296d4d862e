#!/bin/bash
# CASETIMEOUT=600
# l23 (new, class 4: a function object given twice - a user appends a second `functions { fluidProbes { ... } }` block
# to controlDict, or includes a file that defines it again - OpenFOAM merges them silently): the short preview sb with
# (a) a second `functions { fluidProbes { probeLocations ((1e-7 5e-6 0)); } }` at the end of controlDict; (b) a second
# `fluidProbes { ... }` with other fields inside the same functions{}; (c) `#include "moreFunctions"` inside functions{}
# that defines fluidProbes again. Expected: refused naming the duplicated name (the project's rule: a keyword given twice
# is an error), or the merge said; the run sampling other points than the first block's without a word = SILENT.
. "$(dirname "$0")/../lib.sh"
sb; cp -a . $W/b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
one() { tryt 150 "$1" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-260) | probe header: $(head -3 postProcessing/fluidProbes/0/p 2>/dev/null | tr '\n' ' ' | cut -c1-150)"; }
printf '\nfunctions { fluidProbes { probeLocations ((1e-7 5e-6 0)); } }\n' >> system/controlDict; one "(a) a second functions{} block at the end of controlDict"; back
/usr/bin/python3 - system/controlDict <<'P'
import sys
p = sys.argv[1]; t = open(p).read(); i = t.index('functions'); j = t.index('{', i) + 1
t = t[:j] + '\n    fluidProbes { type movingMeshProbes; libs ("libfsi.so"); fields (p); probeLocations ((1e-7 5e-6 0)); }\n' + t[j:]; open(p, 'w').write(t)
P
one "(b) fluidProbes twice inside functions{} (the first now the user's, then the tutorial's)"; back
printf 'fluidProbes { probeLocations ((1e-7 5e-6 0)); }\n' > system/moreFunctions
/usr/bin/python3 - system/controlDict <<'P'
import sys
p = sys.argv[1]; t = open(p).read(); k = t.rindex('}', 0, t.index('#sinclude')); open(p, 'w').write(t[:k] + '    #include "moreFunctions"\n' + t[k:])
P
one "(c) #include moreFunctions (fluidProbes again) at the end of functions{}"; back
