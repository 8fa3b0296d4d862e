#!/bin/bash
# w54: cellMesh fluid box entries at the edges: boxSize 1e300, farSize 1e-300, growthDistance nan, wedgeAngle 0
. "$(dirname "$0")/../lib.sh"
blast; cp system/cellMeshDict ../orig; for e in "boxSize 1e300" "farSize 1e-300" "growthDistance nan" "wedgeAngle 0"; do cp ../orig system/cellMeshDict; k=${e%% *}; v=${e#* }
  /usr/bin/python3 - "$k" "$v" <<'P'
import re,sys
k,v=sys.argv[1],sys.argv[2]; s=open('system/cellMeshDict').read()
m=re.search(r'\nfluid\s*\{',s)
if m is None: s+='\nfluid\n{\n    boxSize 20e-6;\n    nearSize 0.5e-6;\n    farSize 2e-6;\n    growthDistance 5e-6;\n}\n'; m=re.search(r'\nfluid\s*\{',s)
body_start=m.end(); s2=re.sub(r'(\n\s*)'+k+r'\s+[^;]*;', r'\g<1>'+k+' '+v+';', s[body_start:], count=1)
if s2==s[body_start:]: s2='\n    '+k+' '+v+';'+s2
open('system/cellMeshDict','w').write(s[:body_start]+s2)
P
  try "fluid $e" cellMesh; done
