#!/bin/bash
# Mesh convergence of the full protocol on $CASE (averageCell, the
# default, or validationCell): the cellMesh sizes scaled by each factor
# given (default 1.4 1 0.7), parameter set $SET (default: the case's).
# Prints one row per mesh: elements, delta0 [um], F_B, the nine peaks [nN],
# F_E, Newton iterations, wall and CPU time [s], peak memory [MB] of
# cellIndentationFoam. Fails if cellMesh fails (no fallback mesh here).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
work=${WORK:-$(mktemp -d)}
case=${CASE:-averageCell}
for s in ${@:-1.4 1 0.7}
do
    c=$work/${case}_$s
    rm -rf "$c"
    cp -r "$here/$case" "$c"
    (
        cd "$c"
        /usr/bin/python3 - "$s" "${SET:-}" <<'PY'
import re, sys
f = float(sys.argv[1])
p = "system/cellMeshDict"
t = open(p).read()
for k in ("nucleusSize", "cytoplasmSize", "membraneSize", "contactSize"):
    t = re.sub(r"(%s\s+)([0-9.eE+-]+)" % k,
               lambda m: m.group(1) + "%.4g" % (float(m.group(2))*f), t)
open(p, "w").write(t)
p = "constant/solidProperties"
t = open(p).read()
if sys.argv[2]:
    t = re.sub(r"parameterSet\s+\w+;", "parameterSet %s;" % sys.argv[2], t)
open(p, "w").write(t)
PY
        cellMesh > log.cellMesh 2>&1 || { tail log.cellMesh; exit 1; }
        /usr/bin/time -f "peakMemory %M kB" -o log.time \
            cellIndentationFoam > log.cellIndentationFoam 2>&1
        /usr/bin/python3 - "$s" <<'PY'
import re, sys
log = open("log.cellIndentationFoam").read()
ne = re.search(r"(\d+) elements", log).group(1)
wall = re.search(r"wall time ([0-9.]+) s", log).group(1)
cpu = re.search(r"CPU time ([0-9.]+) s", log).group(1)
its = re.search(r"(\d+) Newton iterations", log).group(1)
mem = int(re.search(r"peakMemory (\d+) kB", open("log.time").read()).group(1))
m = re.search(r"delta0 = ([0-9.eE+-]+) m", log)
d0 = float(m.group(1))*1e6 if m else 1.41
peaks = {l.split()[0]: float(l.split()[3])*1e9
         for l in open("postProcessing/indentation/peaks.dat")
         if not l.startswith("#")}
keys = ["endB"] + ["C%d,%s" % (a, b) for a in (1, 2, 3)
                   for b in ("i", "ii", "iii")] + ["endE"]
print("| %s | %s | %.3f | " % (sys.argv[1], ne, d0)
      + " | ".join("%.3f" % peaks.get(k, float("nan")) for k in keys)
      + " | %s | %s | %s | %.0f |" % (its, wall, cpu, mem/1024))
PY
    )
done
