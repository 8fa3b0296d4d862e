#!/bin/bash
# k21 (class 4/6, incidentWindow.py's numbers): on pw (a finished preview with planeWave's reference): the plain run, then --series 0 2 0 (a zero step), --series 2 0 0.5 (reversed), --series 0 2 -0.5, --series 0 1e9 1e-9 (1e18 samples), --series nan nan nan, --level nan, --level inf, --foot -1e400. Expected: the plain run rc 0; every other refused naming the option and its valid range, or handled without a hang (120 s KILL) or a memory blow-up; never numbers printed for a nan level.
. "$(dirname "$0")/../lib.sh"
pwd0; iw .; head -4 $W/try.log | cut -c1-160 | sed 's/^/   /'
for a in "--series 0 2 0" "--series 2 0 0.5" "--series 0 2 -0.5" "--series 0 1e9 1e-9" "--series nan nan nan" "--level nan" "--level inf" "--foot -1e400"; do iw . $a; tail -1 $W/try.log | cut -c1-160 | sed 's/^/   last line: /'; done
