#!/bin/bash
# CASETIMEOUT=600
# n28 (new, class 4: a keyword given twice by two included files - neither in the including file itself - and through a
# nested include): the short preview's constant/fsiProperties coupling{}: (a) `#include "tolA"` (tolerance
# 2e-4) and `#include "tolB"` (tolerance 1e-4); (b) the same file included twice (`#include "tolA"` twice); (c) coupling{
# #include "outer" } with outer holding `#include "inner"` (tolerance 2e-4) and then tolerance 1e-4; (d) the same three
# in constant/solidProperties at the top level (shearViscosity). Expected: each refused naming both places (fix19j's rule:
# a scope's own entries given twice); the later value taken without a word = UNCLEAR (o07's class).
. "$(dirname "$0")/../lib.sh"
ins() { /usr/bin/python3 - "$@" <<'P'
import sys, re
p, scope, text = sys.argv[1], sys.argv[2], sys.argv[3].replace("\\n", "\n")
t = open(p).read()
if scope == "top":
    m = re.search(r"\n(\s*)shearViscosity\s", t); t = t[:m.start()] + "\n" + text + t[m.start():]
    t = re.sub(r"\n\s*shearViscosity\s+[^;]*;", "\n", t, count=1)
else:
    m = re.search(r"\n%s\s*\{\s*\n" % scope, t); t = t[:m.end()] + text + "\n" + t[m.end():]
    t = re.sub(r"(\n%s\s*\{.*?)\n\s*tolerance\s+[^;]*;" % scope, r"\1", t, count=1, flags=re.S)
open(p, "w").write(t)
P
}
run1() { tryt 200 "$1" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-260)"; }
sb; cp -a . $W/s0; printf 'tolerance 2e-4;\n' > constant/tolA; printf 'tolerance 1e-4;\n' > constant/tolB; cp constant/tol? $W/
ins constant/fsiProperties coupling '    #include "tolA"\n    #include "tolB"'; grep -n -A3 '^coupling' constant/fsiProperties | head -4 | tr '\n' ' '; echo; run1 "(a) tolerance by two includes"
cd $W; rm -rf blast; cp -a s0 blast; cd blast; cp $W/tol? constant/; ins constant/fsiProperties coupling '    #include "tolA"\n    #include "tolA"'; run1 "(b) the same include twice"
cd $W; rm -rf blast; cp -a s0 blast; cd blast; printf '#include "inner"\n' > constant/outer; printf 'tolerance 2e-4;\n' > constant/inner; ins constant/fsiProperties coupling '    #include "outer"\n    tolerance 1e-4;'; run1 "(c) a nested include then the key"
cd $W; rm -rf blast; cp -a s0 blast; cd blast; printf 'shearViscosity 0.3;\n' > constant/visA; printf 'shearViscosity 0.1;\n' > constant/visB; ins constant/solidProperties top '#include "visA"\n#include "visB"'; grep -n 'visA\|visB\|shearViscosity' constant/solidProperties | head -4 | tr '\n' ' '; echo; run1 "(d) solidProperties shearViscosity by two includes"
