#!/bin/bash
# v07: sod: setRiemannProblem with the right state missing
. "$(dirname "$0")/../lib.sh"
sod; python3 - <<'P'
import re; f='system/riemannProblemDict'; s=open(f).read(); s=re.sub(r'right\s*\{[^}]*\}','',s); open(f,'w').write(s)
P
setRiemannProblem > log.sr 2>&1; rc=$?; grep -A4 "FATAL" log.sr | head -6; echo "rc=$rc"
