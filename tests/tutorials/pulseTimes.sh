#!/bin/bash
# The blast Allruns write the pulse of -pulse T into 0/p's table exactly:
# its ramp's end T + 1e-10 s after T for every T of -pulse's range (adv38
# x60, x65: written with %.6g, T + 1e-10 printed as T for T >= 1e-4 s,
# and the solver refused "table row 4 at time ... is not after row 3", a
# table the user never wrote; pulseStudy's durations the same). The
# axisymmetric preview and the 3D quarter prepared with -pulse 1e-3 and
# -pulse 0.9 (the range's end), -noRun, smallest meshes: the table's
# times strictly increase and rows 3 and 4 are T and T + 1e-10 to the
# last digit.
set -uo pipefail
. "$(dirname "$0")/../lib/checks.sh"
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT

# rows CASE: the times of 0/p's pulse table, one a line
rows()
{
    /usr/bin/python3 - "$1/0/p" <<'PY'
import re, sys
s = open(sys.argv[1]).read()
m = re.search(r"uniformValue\s+table\s*\d*\s*\((.*?)\n\s*\)\s*;", s, re.S)
for t, _ in re.findall(r"\(\s*([^()\s]+)\s+([^()\s]+)\s*\)", m.group(1)):
    print(t)
PY
}
# exact CASE T: rows 3 and 4 are T and T + 1e-10 (as doubles), the times
# strictly increasing
exact()
{
    rows "$1" | /usr/bin/python3 -c "
import sys
t = [float(x) for x in sys.stdin.read().split()]
T = float(sys.argv[1])
sys.exit(0 if t[2] == T and t[3] == T + 1e-10
         and all(a < b for a, b in zip(t, t[1:])) else 1)" "$2"
}

for T in 1e-3 0.9
do
    c=$work/preview$T
    mkdir -p "$c"
    cp -r "$root/tutorials/blast/axisymmetricPreview"/{0.orig,system,constant,Allrun,Allclean} "$c"/
    (cd "$c" && ./Allrun -h 0.25e-6 -far 2e-6 -cell 0.5e-6 -Z 30e-6 \
        -endTime 2e-9 -pulse $T -noRun > log.allrun 2>&1)
    check "preview -pulse $T: 0/p's ramp ends at T + 1e-10 s exactly, times increasing ($(rows "$c" | tr '\n' ' '))" \
        "exact '$c' $T"
    c=$work/quarter$T
    mkdir -p "$c"
    cp -r "$root/tutorials/blast/quarter3D"/{0.orig,system,constant,Allrun,Allclean} "$c"/
    (cd "$c" && ./Allrun -box 30e-6 -h 0.6e-6 -far 2e-6 -growth 5e-6 \
        -cell 1.4e-6 -endTime 2e-9 -pulse $T -noRun > log.allrun 2>&1)
    check "quarter3D -pulse $T: 0/p's ramp ends at T + 1e-10 s exactly, times increasing ($(rows "$c" | tr '\n' ' '))" \
        "exact '$c' $T"
done
exit $fail
