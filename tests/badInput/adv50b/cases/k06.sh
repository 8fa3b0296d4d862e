#!/bin/bash
# k06 (class 4/silent, elliptic on the 3D quarter, valid): quarter3D scaledCell at 1.4 um with structuredSmoothing none and elliptic. The user guide: "The element count and the connectivity are those of none", the log prints the sweeps. Expected: both meshed, equal element counts, elliptic's smallest scaled Jacobian > 0, the log naming the sweeps; elliptic's mesh differs from none's (else the entry did nothing, silently).
. "$(dirname "$0")/../lib.sh"
qm; mset nucleusShape scaledCell; cm; cp constant/cell.msh $W/none.msh; grep -a -i -m3 'hexahedra\|elements' $W/try.log | cut -c1-160
mset structuredSmoothing elliptic; cm; grep -a -i -m3 'hexahedra\|elements\|sweep' $W/try.log | cut -c1-160
pyw - $W/none.msh constant/cell.msh <<'P'
import sys
def els(p):
    t = open(p).read(); i = t.index('$Elements'); h = t[i:].split('\n')[1].split(); return int(h[1])
def nodesum(p):
    t = open(p).read(); i = t.index('$Nodes'); j = t.index('$EndNodes'); return len(t[i:j])
a, b = sys.argv[1:3]
print('   elements none %d, elliptic %d; node blocks %s' % (els(a), els(b), 'identical' if open(a).read()[open(a).read().index('$Nodes'):open(a).read().index('$EndNodes')] == open(b).read()[open(b).read().index('$Nodes'):open(b).read().index('$EndNodes')] else 'differ'))
P
