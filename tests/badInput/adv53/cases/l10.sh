#!/bin/bash
# CASETIMEOUT=600
# l10 (new, class 6: few file descriptors, `ulimit -n`, for the Python tools, which no pass limited - f61 limited the
# solvers): on pwd0 (the finished preview with its reference): planeWave -case . -check, incidentWindow.py, plotBlast.py
# under ulimit -n 12 and 6; the indentation idn: plotIndentation.py; tests/blast/runPreview.sh D -noRun (its Allrun
# with allrunLock's Python) under ulimit -n 10. Expected: each runs or stops naming the limit (Too many open files) in
# one line; a Python traceback = CRASH (low); a half-written output = DATALOSS.
. "$(dirname "$0")/../lib.sh"
lim() { local n=$1 l=$2; shift 2; tryt 200 "$l (ulimit -n $n)" bash -c "ulimit -n $n; exec \"\$@\"" _ "$@"; echo "   tracebacks $(grep -a -c Traceback $W/try.log) | last: $(grep -a -v '^ *$' $W/try.log | tail -1 | cut -c1-220)"; }
pwd0; for n in 12 6; do lim $n "planeWave -check" planeWave -case . -check; lim $n "incidentWindow.py" /usr/bin/python3 $ROOT/bench/blast/analysis/incidentWindow.py .; lim $n "plotBlast.py" /usr/bin/python3 $ROOT/tutorials/blast/plotBlast.py .; done
cd $W; idn; lim 8 "plotIndentation.py" /usr/bin/python3 $ROOT/tutorials/indentation/plotIndentation.py .
cd $W; lim 10 "runPreview.sh D -noRun" bash $ROOT/tests/blast/runPreview.sh $W/D -h 0.5e-6 -far 4e-6 -dz 0.5e-6 -cell 1e-6 -Z 20e-6 -endTime 2e-9 -noPlots -noVTK -noRun; echo "   D: $(ls $W/D/axisymmetricPreview 2>/dev/null | tr '\n' ' ' | cut -c1-200)"
