#!/bin/bash
# i45 (class 5/SILENT, paperFigures -noRun over a tutorials tree with a half-finished or restarted preview): T = a copy of the
# tutorials folder whose blast/axisymmetricPreview is (a) bd (the small 2 ns run, other options than paperDict's), (b) bd
# with its .allrunOptions rewritten to the default options (none) and its solver log cut (a killed run), (c) as (b) but the
# log whole: `paperFigures -case P -noRun -results T -output O` (P a copy of tutorials/paper whose paperDict keeps blast5ns only, since P2: P1 ran
# it where no system/paperDict is, P1b stopped at averageCell, not current) must not take (a) (b) as the paper's 5 ns run: it refuses (-noRun
# cannot run them) naming the run and why (options, not finished), or leaves them out saying so; never figures made from
# them as if current. Nothing in T changed.
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials" $W/T; cp -r "$ROOT/tutorials/paper" $W/P; /usr/bin/python3 - $W/P/system/paperDict <<'Q'
import re, sys
p = sys.argv[1]; t = open(p).read()
t = "\n".join(l for l in t.split("\n") if not re.match(r"\s*(averageCell|validationCell|blast10ns|blast15ns|quarter3D)\s*\{", l)); open(p, "w").write(t)
Q
grep -a "tutorial" $W/P/system/paperDict | sed "s/^/   paperDict: /"; bd; B=$PWD; for x in a b c; do
  rm -rf $W/T/blast/axisymmetricPreview; cp -a $B $W/T/blast/axisymmetricPreview; cd $W/T/blast/axisymmetricPreview
  [ $x != a ] && printf '{\n "program": "Allrun",\n "options": {}\n}\n' > .allrunOptions
  ls log.* | tr '\n' ' '; echo; L=$(ls log.cellBlastFoam log.first 2>/dev/null | head -1); [ $x = b ] && [ -n "$L" ] && { head -c $(( $(stat -c %s $L) / 2 )) $L > $L.x; mv $L.x $L; }
  cd $W; (cd $W/T && find . -type f | sort | xargs md5sum) > $W/t0; rm -rf $W/O
  tryt 300 "($x) paperFigures -noRun" paperFigures -case $W/P -noRun -results $W/T -output $W/O; tail -5 $W/try.log | cut -c1-220 | sed 's/^/   /'
  echo "   output: $(ls $W/O 2>/dev/null | head -20 | tr '\n' ' ') | T changed: $(cd $W/T && md5sum -c --quiet $W/t0 2>&1 | head -5 | tr '\n' ' ')"; grep -a -i 'blast5ns\|axisymmetricPreview' $W/O/README.md 2>/dev/null | head -3 | cut -c1-200 | sed 's/^/   README: /'; done
