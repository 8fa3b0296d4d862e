#!/bin/bash
# w75: solidProperties materials at the edges: membrane d0 0, d0 -1e-9, nucleus C0 nan, an empty materials {} and a region missing (membrane removed)
. "$(dirname "$0")/../lib.sh"
blast; cp constant/solidProperties ../sp; f=constant/solidProperties
sed -i 's/d0          9.5125e-10;/d0 0;/' $f; try "d0 0" cellBlastFoam; cp ../sp $f; sed -i 's/d0          9.5125e-10;/d0 -1e-9;/' $f; try "d0 -1e-9" cellBlastFoam
cp ../sp $f; sed -i '0,/C0 1450;/s//C0 nan;/' $f; try "nucleus C0 nan" cellBlastFoam
cp ../sp $f; /usr/bin/python3 - <<'P'
import re; s=open('constant/solidProperties').read(); i=s.index('\nmaterials'); j=s.index('\ninterfaceProbe'); open('constant/solidProperties','w').write(s[:i]+'\nmaterials\n{\n}\n'+s[j:])
P
try "materials {}" cellBlastFoam
cp ../sp $f; /usr/bin/python3 - <<'P'
import re; s=open('constant/solidProperties').read(); s=re.sub(r'\n    membrane\n    \{[^}]*\}', '', s, count=1); open('constant/solidProperties','w').write(s)
P
try "membrane removed" cellBlastFoam
