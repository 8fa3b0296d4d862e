#!/bin/bash
# g03 (class 1, #include and $variable): the FSI coupling's tolerance reached (a) through `#include "$FOAM_CASE/system/couplingParams"` inside coupling{} (the file in system/, holding "tolerance 1e-4;"), (b) as a $variable: "tol 1e-4;" at the top of fsiProperties and "tolerance $tol;" in coupling. Each finished to 2 ns, the included file / the variable's value changed to 1e-3, restart to 3 ns: refused naming constant/fsiProperties (its parsed contents changed)?
. "$(dirname "$0")/../lib.sh"
blast; /usr/bin/python3 - constant/fsiProperties <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read()
t = re.sub(r'(coupling\s*\{)', r'\1\n    #include "$FOAM_CASE/system/couplingParams"', t, 1)
t = re.sub(r'\n\s*tolerance\s+1e-4;[^\n]*', '\n', t, 1); open(p, 'w').write(t)
P
echo 'tolerance 1e-4;' > system/couplingParams; run 120 cellBlastFoam > log.first 2>&1; fatal log.first 3; echo "   (a) first run: times $(ls -d [1-9]* | tr '\n' ' ')"
latest; blastEnd 3e-9 1e-9; echo 'tolerance 1e-3;' > system/couplingParams; sums > ../s.a
tryf "(a) included tolerance 1e-4 -> 1e-3, restart" cellBlastFoam; grep -a -A3 'other inputs' $W/try.log | head -4 | cut -c1-200; nochange ../s.a
cd $W; rm -rf blast; blast; /usr/bin/python3 - constant/fsiProperties <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read()
t = re.sub(r'(\ninterface\s*\{)', r'\ntol 1e-4;\n\1', t, 1)
t = re.sub(r'(\n\s*tolerance\s+)1e-4;', r'\1$tol;', t, 1); open(p, 'w').write(t)
P
grep -n 'tol' constant/fsiProperties | head -3
tryf "(b) first run with a \$variable" cellBlastFoam; echo "   times $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"
if [ -d 2e-09 ]; then latest; blastEnd 3e-9 1e-9; sed -i 's/^tol 1e-4;/tol 1e-3;/' constant/fsiProperties; sums > ../s.b; tryf "(b) \$tol 1e-4 -> 1e-3, restart" cellBlastFoam; grep -a -A3 'other inputs' $W/try.log | head -4 | cut -c1-200; nochange ../s.b; fi
