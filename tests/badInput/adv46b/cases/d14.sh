#!/bin/bash
# d14 (class 1, blast restart after constant/thermophysicalProperties edited): (a) mieGruneisenCoeffs entries reordered and commented: accepted; (b) Gamma0 0.1 -> 0.10000000000000001 (the same double) accepted; (c) Gamma0 0.1000001: refused naming the entry.
. "$(dirname "$0")/../lib.sh"
bd; rs; cp constant/thermophysicalProperties ../tp
python3 - constant/thermophysicalProperties <<P
import re,sys; p=sys.argv[1]; t=open(p).read(); m=re.search(r"mieGruneisenCoeffs\s*\{([^}]*)\}", t); body=m.group(1).strip().splitlines(); body.reverse()
open(p,"w").write(t[:m.start()]+"mieGruneisenCoeffs // reordered\n{\n"+"\n".join("  "+l.strip()+"  // mine" for l in body)+"\n}"+t[m.end():])
P
tryt 240 "(a) reordered" cellBlastFoam; cont; after
for v in 0.10000000000000001 0.1000001; do cd $W; rm -rf blast; bd; rs; sed -i "s/Gamma0  0.1; /Gamma0  $v; /" constant/thermophysicalProperties; grep -c "Gamma0  $v" constant/thermophysicalProperties; tryt 240 "Gamma0 $v" cellBlastFoam; cont; after; done
