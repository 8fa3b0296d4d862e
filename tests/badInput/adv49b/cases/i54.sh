#!/bin/bash
# i54 (class 5/SILENT, the subcycled run's solidState without its step-start force): mbd (subcycles 4, 5e-9) restarted to 6e-9
# with -acceptEdited after the `interfaceForce` entry of 5e-09/uniform/solidState (the force f_n of the step's start, the
# user guide) (a) removed, (b) set to zeros (same length); (c) the clean restart. (a) refused naming the file and the missing
# entry (never taken as zero); (b) an edit on purpose: run, but then (b) differs from (c) (shown).
. "$(dirname "$0")/../lib.sh"
mbd; rs6; cd $W; cp -a mblast ref; cd ref; cellBlastFoam > log.r 2>&1 || echo "ref failed"; cd $W/mblast; F=5e-09/uniform/solidState
echo "   solidState entries: $(grep -a -o '^ *[A-Za-z0-9_]\+' $F | tr -d ' ' | sort -u | tr '\n' ' ')"; cp $F ../ss0
/usr/bin/python3 - $F <<'P'
import re, sys
p = sys.argv[1]; t = open(p, encoding='latin-1').read(); m = re.search(r'\n\s*interfaceForce\b[^;]*;', t, re.S)
print("   interfaceForce entry: %s" % ("%d chars, removed" % len(m.group(0)) if m else "NOT FOUND")); 
if m: open(p, 'w', encoding='latin-1').write(t[:m.start()] + t[m.end():])
P
tryt 300 "(a) interfaceForce removed, -acceptEdited" cellBlastFoam -acceptEdited; cont; rm -rf 6e-09; cp ../ss0 $F
/usr/bin/python3 - $F <<'P'
import re, sys
p = sys.argv[1]; t = open(p, encoding='latin-1').read(); m = re.search(r'(\n\s*interfaceForce\b)([^;]*)(;)', t, re.S)
if m:
    body = re.sub(r'-?\d+\.?\d*(e[-+]?\d+)?', lambda x: '0' if '.' in x.group(0) or 'e' in x.group(0) else x.group(0), m.group(2))
    open(p, 'w', encoding='latin-1').write(t[:m.start(2)] + body + t[m.end(2):]); print("   interfaceForce zeroed (%d chars)" % len(body))
P
tryt 300 "(b) interfaceForce zeroed, -acceptEdited" cellBlastFoam -acceptEdited; cont; [ -d 6e-09 ] && cmp6 $W/ref
