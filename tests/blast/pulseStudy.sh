#!/bin/bash
# pulseStudy (issue 20) on two points of a short preview (a 30 um column,
# coarse far water, 22 ns, as smoke.sh): overpressure 30 and 50 MPa, 3 ns.
# Asserts (checkPulseStudy.py):
#  - the table against each point's own outputs: the pulse table of its
#    0/p (the overpressure reached the pulse), the region peaks of
#    pressure, von Mises and temperature rise against solid.h5 read
#    directly, the interface peaks against the solver's interface maxima,
#    and the solid.h5 interface maxima equal to the solver's at the write
#    times (the interface elements and region names are the solver's);
#  - the peak nucleus pressure scales with the overpressure (ratio 0.6);
#  - a second run runs nothing (both points finished earlier; table.csv
#    unchanged byte for byte);
#  - a changed base option is refused naming baseOptions, nothing run;
#  - a point whose result is gone (an interrupted point) is the only one
#    run again, with the same table.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/etc/bashrc"
work=${TMPDIR:-/tmp}/pulseStudySmoke.$$
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/study/system"
study=$work/study
dict=$study/system/pulseStudyDict
# the tutorial's dictionary with the short preview and a 2-point grid
sed -e "s|^baseCase .*|baseCase \"$root/tutorials/blast/axisymmetricPreview\";|" \
    -e "s|^baseOptions .*|baseOptions (-h 0.25e-6 -far 2e-6 -cell 0.5e-6 -Z 30e-6 -endTime 2.2e-8);|" \
    -e "s|^overpressure .*|overpressure (30e6 50e6);|" \
    -e "s|^duration .*|duration (3e-9);|" \
    "$root/tutorials/blast/pulseStudy/system/pulseStudyDict" > "$dict"
run() { /usr/bin/python3 "$root/applications/utilities/pulseStudy/pulseStudy.py" -case "$study" "$@"; }
fail() { echo "FAIL: $*"; exit 1; }

run -keep > "$work/run1.log" 2>&1 || { cat "$work/run1.log"; fail "first run"; }
cat "$work/run1.log"
grep -q "0 finished earlier, 2 to run" "$work/run1.log" || fail "first run: not 2 points to run"
/usr/bin/python3 "$here/checkPulseStudy.py" "$study"
cp "$study/postProcessing/pulseStudy/table.csv" "$work/table1.csv"

# again: nothing runs, the same table
run > "$work/run2.log" 2>&1 || { cat "$work/run2.log"; fail "second run"; }
grep -q "2 finished earlier, 0 to run" "$work/run2.log" \
    || { cat "$work/run2.log"; fail "the second run ran points"; }
cmp "$work/table1.csv" "$study/postProcessing/pulseStudy/table.csv" \
    || fail "the second run's table differs"
echo "ok   second run: nothing run, table.csv unchanged"

# a changed input of the finished points: refused, nothing run
cp "$dict" "$work/dict"
sed -i "s|^baseOptions .*|baseOptions (-h 0.25e-6 -far 2e-6 -cell 0.4e-6 -Z 30e-6 -endTime 2.2e-8);|" "$dict"
if run > "$work/run3.log" 2>&1; then cat "$work/run3.log"; fail "changed baseOptions accepted"; fi
grep -q "pulseStudyDict: entry 'baseOptions' differs from that of the finished point" "$work/run3.log" \
    || { cat "$work/run3.log"; fail "the refusal does not name baseOptions"; }
! grep -q "to run" "$work/run3.log" || fail "changed baseOptions: something ran"
echo "ok   changed baseOptions refused: $(grep -o "entry 'baseOptions'.*point [^ ]*" "$work/run3.log")"
cp "$work/dict" "$dict"

# an interrupted point (its result gone, its folder left): run again alone
rm "$study/postProcessing/pulseStudy/points/p5e+07_T3e-09/result.json"
run > "$work/run4.log" 2>&1 || { cat "$work/run4.log"; fail "fourth run"; }
grep -q "1 finished earlier, 1 to run" "$work/run4.log" \
    || { cat "$work/run4.log"; fail "not the interrupted point alone"; }
grep -q "p5e+07_T3e-09: overpressure 5e+07 Pa, duration 3e-09 s: done" "$work/run4.log" \
    || { cat "$work/run4.log"; fail "the interrupted point did not run"; }
# the solver's results are deterministic: the same table but for the
# wall and CPU times (the last two columns)
diff <(cut -d, -f1-$(( $(head -1 "$work/table1.csv" | tr ',' '\n' | wc -l) - 2 )) "$work/table1.csv") \
     <(cut -d, -f1-$(( $(head -1 "$work/table1.csv" | tr ',' '\n' | wc -l) - 2 )) "$study/postProcessing/pulseStudy/table.csv") \
    || fail "the rerun point's indicators differ"
[ ! -d "$study/postProcessing/pulseStudy/points/p5e+07_T3e-09/case" ] \
    || fail "the rerun point's case was kept without -keep"
echo "ok   interrupted point run again alone, same indicators"
