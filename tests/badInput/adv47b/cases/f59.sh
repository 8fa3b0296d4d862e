#!/bin/bash
# f59 (class 1/2, paperFigures' run reused after its options changed): a paper case whose paperDict holds only blast5ns with the small preview's options (20 um column, 2 ns); paperFigures runs it in postProcessing/runs/blast5ns (the figures may fail for want of the other runs: said). Then the options changed (-pulse 3e-9) and paperFigures -noRun: the earlier run is not used as the new one (said not current / refused, naming blast5ns and the option), its folder kept; never figures from the 5 ns run labelled with the new options.
. "$(dirname "$0")/../lib.sh"
cp -r $ROOT/tutorials/paper $W/paper; cd $W/paper; /usr/bin/python3 - system/paperDict <<'P'
import re, sys
p = sys.argv[1]; t = open(p).read()
t = re.sub(r"cases\s*\{.*?\n\}", "cases\n{\n    blast5ns { tutorial blast/axisymmetricPreview; options (-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 20e-6 -endTime 2e-9 -writeInterval 1e-9); }\n}", t, flags=re.S)
open(p, "w").write(t)
P
grep -A2 '^cases' system/paperDict | tr -s ' ' | cut -c1-200
tryt 280 "(a) paperFigures, one small run" paperFigures; tail -4 $W/try.log | cut -c1-250; ls postProcessing/runs 2>/dev/null | tr '\n' ' '; echo
sed -i 's/-endTime 2e-9 -writeInterval 1e-9)/-endTime 2e-9 -writeInterval 1e-9 -pulse 3e-9)/' system/paperDict; grep -c 'pulse 3e-9' system/paperDict
tryt 120 "(b) -noRun after -pulse 3e-9 was added" paperFigures -noRun; grep -a -i 'blast5ns\|current\|option\|pulse' $W/try.log | head -6 | cut -c1-250; ls postProcessing/runs 2>/dev/null | tr '\n' ' '; echo
