#!/bin/bash
# q16: blast finished; the user then REMOVES the fluidProbes function object from system/controlDict (functions {}) and keeps a note in postProcessing/fluidProbes/0/; -overwrite from 0: the old probe log and the note kept (the new run no longer writes there) or refused naming them?
. "$(dirname "$0")/../lib.sh"
blastDone; echo "q16 note" > postProcessing/fluidProbes/0/notes.txt; md5sum postProcessing/fluidProbes/0/p > ../pmd5
/usr/bin/python3 - <<'P'
import re; s = open('system/controlDict').read(); i = s.index('functions'); j = s.index('#sinclude'); open('system/controlDict', 'w').write(s[:i] + 'functions {}\n\n' + s[j:])
P
grep -c fluidProbes system/controlDict; tryf "-overwrite without fluidProbes" cellBlastFoam -overwrite; kept "q16 note"; md5sum -c ../pmd5 2>&1 | tail -1; ls postProcessing | tr '\n' ' '; echo
