#!/bin/bash
# k12 (class 4/silent, oGrid orthogonal keeps the count): the quarter's hex water straight and orthogonal, and the full3D box orthogonal (30 um box, 1 um near, 2 um lateral). The guide: the O-grid nodes moved, the counts the same, mirrored across x = y. Expected: equal hexahedra and node counts straight/orthogonal in each mode, full3D's cellInterface faces 4x the quarter's, no inverted cell; the orthogonal mesh differs from the straight one.
. "$(dirname "$0")/../lib.sh"
cnt() { pyw - constant/fluid.msh <<'P'
import sys
t = open(sys.argv[1]).read(); i = t.index('$Elements'); n = int(t[i:].split('\n')[1]); j = t.index('$Nodes'); m = int(t[j:].split('\n')[1])
print('elements %d nodes %d md5-nodes %d' % (n, m, hash(t[j:t.index('$EndNodes')]) % 100000))
P
}
qm; cm "" 300; echo "   quarter straight: $(cnt)"; qm "" "oGrid orthogonal;"; cm "" 300; echo "   quarter orthogonal: $(cnt) | $(grep -a -i -m1 'sweep' $W/try.log | cut -c1-120)"
qm; mset mode full3D; cm "" 300; echo "   full straight: $(cnt)"; qm "" "oGrid orthogonal;"; mset mode full3D; cm "" 400; echo "   full orthogonal: $(cnt) | $(grep -a -i -m1 'sweep' $W/try.log | cut -c1-120)"
