#!/bin/bash
# i18: ind: materials region nucleus removed (include replaced by two regions)
. "$(dirname "$0")/../lib.sh"
ind; cat $PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4 | head -0; python3 - <<'P'
import re
f='constant/solidProperties'; s=open(f).read()
src=open(__import__('os').environ['PROJECT_DIR']+'/etc/caseDicts/cellMaterials/textFactor4').read()
m=re.search(r'nucleus\s*\{[^}]*\}', src); print('nucleus block found', bool(m))
s=s.replace('#include "$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4"', src.replace(m.group(0),''))
open(f,'w').write(s)
P
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
