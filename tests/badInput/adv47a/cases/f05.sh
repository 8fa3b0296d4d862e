#!/bin/bash
# f05 (class 5+1+2, adv46b d65 for the indentation's restart: the smoke indentation with 0.01 um steps SIGKILLed after its
# first checkpoint (ik), startFrom latestTime): (a) postProcessing/indentation/restart.h5 removed and the nucleus's mu1
# changed; (b) restart.h5 removed, inputs unchanged; (c) force.dat removed; (d) materials.dat removed and mu1 changed.
# Each refused naming the file, nothing of the earlier results lost (force.dat, peaks.dat, solid.h5 unchanged); never a
# run that starts over the results or continues with the changed mu1 without a word. Cut at 60 s each.
. "$(dirname "$0")/../lib.sh"
ik; cp -a . ../keep; sums > ../s
mu() { sed 's/431.12;/777;/' "$ROOT/etc/caseDicts/cellMaterials/textFactor4" > $W/tf4; sed -i "s|\$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4|$W/tf4|" constant/solidProperties; echo "   nucleus mu1 777 through $(grep -c "$W/tf4" constant/solidProperties) include of a copy of textFactor4"; }
one() { tryt 60 "$1" cellIndentationFoam; after; echo "   changed since the kill: $(changed ../s)"; cd $W; rm -rf ind; cp -a keep ind; cd ind; }
rm postProcessing/indentation/restart.h5; mu; one "(a) restart.h5 removed, mu1 changed"
rm postProcessing/indentation/restart.h5; one "(b) restart.h5 removed"
rm postProcessing/indentation/force.dat; one "(c) force.dat removed"
rm postProcessing/indentation/materials.dat; mu; one "(d) materials.dat removed, mu1 changed"
