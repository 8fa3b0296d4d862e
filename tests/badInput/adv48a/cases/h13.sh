#!/bin/bash
# CASETIMEOUT=900
# h13 (classes 1, 4, 5: adv46b's low rows that fix19d closed, varied): (a) d02 (b): the killed indentation restarted with
# the materials from a copy included as constant/mats whose membrane C10 changed: refused naming materials/membrane/C10
# and constant/mats; (b) the same copy unchanged but a comment added: continues; (c) d10 (a): 'fixed' with a row given
# twice: the same set (continues, or refused naming the duplicate); (d) d14 (a): the preview restarted with
# fsiProperties' coupling entries reordered: continues or refused naming the order; (e) d36: misspelt words of
# fsiProperties (scheme Robin, onNonConvergence Warn, load Pressure) and cellMeshDict (mode axiSymmetric, nucleusShape
# centredspheroid): each refused naming the entry, the file and the closest valid word.
. "$(dirname "$0")/../lib.sh"
ik; grep -v '^ *//' $ROOT/etc/caseDicts/cellMaterials/textFactor4 > constant/mats; sed -i 's|#include "$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4"|#include "mats"|' constant/solidProperties; rm -f .runLock; cp -a . ../ikeep
sums > ../s0; /usr/bin/python3 - constant/mats <<'P'
import sys; p = sys.argv[1]; t = open(p).read(); k = t.find('C10', t.find('membrane')); e = t.find(';', k); print('   mats:', t[k:e], '-> C10 200'); open(p, 'w').write(t[:k] + 'C10         200' + t[e:])
P
tryt 200 "(a) membrane C10 changed in constant/mats (included)" cellIndentationFoam; cont; echo "   changed: $(changed ../s0 | tr '\n' ' ')"
cd $W; rm -rf ind; cp -a ikeep ind; cd ind; echo "// a comment" >> constant/mats; tryt 200 "(b) included copy unchanged but a comment" cellIndentationFoam; cont; after
cd $W; rm -rf ind; cp -a ikeep ind; cd ind; sed -i 's/^    (axis 0)                            \/\/ u_r = 0 on the axis/    (axis 0) (axis 0)/' constant/solidProperties; grep -A3 "^fixed" constant/solidProperties | tr '\n' ' '; echo
tryt 200 "(c) fixed: (axis 0) twice" cellIndentationFoam; cont; after
cd $W; bd; rs; /usr/bin/python3 - constant/fsiProperties <<'P'
import re, sys; p = sys.argv[1]; t = open(p).read(); m = re.search(r"coupling\s*\{([^}]*)\}", t); body = [l for l in m.group(1).strip().splitlines()]; body.reverse()
open(p, 'w').write(t[:m.start()] + "coupling\n{\n" + "\n".join("    " + l.strip() for l in body) + "\n}" + t[m.end():])
P
tryt 240 "(d) coupling entries reordered" cellBlastFoam; cont; after
cd $W; rm -rf blast; blast; cp constant/fsiProperties ../f0
for e in "scheme Robin" "onNonConvergence Warn" "load Pressure"; do cp ../f0 constant/fsiProperties; sete constant/fsiProperties $e; tryt 40 "(e) fsiProperties $e" cellBlastFoam; echo "   sig: $(sig) | ran: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"; rm -rf [1-9]* solid postProcessing; done; cp ../f0 constant/fsiProperties
cd $W; ind; cp system/cellMeshDict ../c0; for e in "mode axiSymmetric" "nucleusShape centredspheroid" "nucleusShape scaledCell2"; do cp ../c0 system/cellMeshDict; sete system/cellMeshDict $e; tryt 40 "(e) cellMeshDict $e" cellMesh; done
