#!/bin/bash
# a25 (class 4, paperFigures' dictionary system/paperDict, a tool not attacked hard): in a copy of tutorials/paper: a case's tutorial outside the tutorials folder (../../src), a tutorial that does not exist, options (-np 0) of the quarter, options ("-pulse" without value), a case twice, an unknown case 'blast20ns', peakWindow nan / 0 / 1e400, -noRun with nothing current: each refused before any run, naming the file, the entry and the range?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/paper" $W/paper; cd $W/paper; f=system/paperDict; cp $f ../orig; sums > ../s
t() { tryf "$1" paperFigures -noRun; echo "   runs made: $(ls postProcessing/runs 2>/dev/null | tr '\n' ' ')"; cp ../orig $f; rm -rf postProcessing; }
sed -i 's|tutorial indentation/averageCell;|tutorial ../../src;|' $f; t "averageCell tutorial ../../src"
sed -i 's|tutorial indentation/averageCell;|tutorial indentation/noSuchCell;|' $f; t "averageCell tutorial missing"
sed -i 's|options (-np 2 -lateral 2e-6 -far 10e-6);|options (-np 0 -lateral 2e-6 -far 10e-6);|' $f; t "quarter3D -np 0"
sed -i 's|options (-pulse 10e-9);|options (-pulse);|' $f; t "blast10ns -pulse without value"
sed -i 's|^\( *blast5ns .*\)$|\1\n    blast5ns        { tutorial blast/axisymmetricPreview;  options (); }|' $f; t "blast5ns twice"
sed -i 's|^\( *blast5ns .*\)$|\1\n    blast20ns       { tutorial blast/axisymmetricPreview;  options (-pulse 20e-9); }|' $f; t "unknown blast20ns"
for v in nan 0 1e400 -1; do sed -i "s/^peakWindow .*/peakWindow $v;/" $f; t "peakWindow $v"; done
tryf "-noRun, nothing current" paperFigures -noRun; echo "   changed: $(changed ../s)"
