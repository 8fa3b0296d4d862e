#!/bin/bash
# Mesh convergence of the full protocol on $CASE (averageCell, the
# default, or validationCell): the cellMesh sizes scaled by each factor
# given (default 1.4 1 0.7), the paper's parameter set $SET (table, text,
# textFactor4, instantaneous: etc/caseDicts/cellMaterials; default: the
# case's).
# Prints one row per mesh: elements, delta0 [um], F_B, the nine peaks [nN],
# F_E, Newton iterations, wall and CPU time [s], peak memory [MB] of
# cellIndentationFoam. Fails if cellMesh fails (no fallback mesh here).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
. "$here/../../etc/scratchFolder"
work=${WORK:-$(mktemp -d)}
case=${CASE:-averageCell}
for s in ${@:-1.4 1 0.7}
do
    c=$work/${case}_$s
    # an earlier case of this script only, never a user's folder (adv51
    # n01)
    scratchFolder meshConvergence.sh "$c" @case
    cp -r "$here/$case/." "$c/"
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
    t = re.sub(r"cellMaterials/\w+", "cellMaterials/" + sys.argv[2], t)
open(p, "w").write(t)
PY
        cellMesh > log.cellMesh 2>&1 || { tail log.cellMesh; exit 1; }
        /usr/bin/time -f "peakMemory %M kB" -o log.time \
            cellIndentationFoam > log.cellIndentationFoam 2>&1
        /usr/bin/python3 - "$s" <<'PY'
import re, sys
from neuronFsi import logs, postProcessing
run = logs.indentationRun("log.cellIndentationFoam")
ne, wall, cpu = run["elements"], run["wall"], run["cpu"]
its = run["newtonIterations"]
mem = int(re.search(r"peakMemory (\d+) kB", open("log.time").read()).group(1))
d0 = run["delta0"]*1e6 if run["delta0"] is not None else 1.41
table = postProcessing.readTable("postProcessing/indentation/peaks.dat")
peaks = {label: force*1e9 for label, force in
         zip(table.column("label"), table.column("force"))}
keys = ["endB"] + ["C%d,%s" % (a, b) for a in (1, 2, 3)
                   for b in ("i", "ii", "iii")] + ["endE"]
print("| %s | %s | %.3f | " % (sys.argv[1], ne, d0)
      + " | ".join("%.3f" % peaks.get(k, float("nan")) for k in keys)
      + " | %s | %s | %s | %.0f |" % (its, wall, cpu, mem/1024))
PY
    )
done
