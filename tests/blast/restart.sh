#!/bin/bash
# Restart of cellBlastFoam (issue 5): the preview on a short water column
# (20 um, coarse far field, to 16 ns, a write every 2 ns) run once without
# interruption; a copy killed with SIGKILL after the pulse has reached the
# cell (a time >= 10 ns written) and restarted from its latest time
# (startFrom latestTime). Asserts that the restarted run reproduces the
# uninterrupted one at every step after the restart time: solid probes
# (pressure, von Mises, strains, rates at the three interface probes) and
# coupling log (time, dt, iterations, converged: exactly; interface force,
# largest interface velocity) within 1e-10 of each column's range (the
# differences are printed; not bitwise yet: ulp-level differences remain).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
work=${TMPDIR:-/tmp}/blastRestart.$$
trap 'rm -rf "$work"' EXIT
opts=(-h 0.25e-6 -far 2e-6 -cell 0.5e-6 -Z 20e-6 -endTime 1.6e-8 -noPlots)

# Reference: uninterrupted, writes every 2 ns
bash "$here/runPreview.sh" "$work/ref" "${opts[@]}" -noRun \
    > "$work.ref.log" 2>&1 || { cat "$work.ref.log"; exit 1; }
ref=$work/ref/axisymmetricPreview
(
    cd "$ref"
    foamDictionary -entry writeInterval -set 2e-9 system/controlDict >/dev/null
    foamDictionary -entry endTime -set 1.6e-8 system/controlDict >/dev/null
    rm -rf postProcessing solid
)
cp -r "$ref" "$work/killed"
killed=$work/killed
(cd "$ref" && cellBlastFoam > log.cellBlastFoam 2>&1) \
    || { tail -20 "$ref/log.cellBlastFoam"; exit 1; }

# Killed: SIGKILL once 1.2e-08 is written, then restart from the latest time
(
    cd "$killed"
    cellBlastFoam > log.first 2>&1 &
    pid=$!
    while [ ! -f 1.2e-08/uniform/fsiState ]
    do
        kill -0 $pid 2>/dev/null || { tail log.first; exit 1; }
        sleep 0.2
    done
    kill -KILL $pid
    wait $pid 2>/dev/null || true
    latest=$(foamListTimes -latestTime 2>/dev/null | tail -1)
    echo "killed after t = $latest s was written"
    foamDictionary -entry startFrom -set latestTime system/controlDict \
        > /dev/null
    cellBlastFoam > log.restart 2>&1 || { tail -20 log.restart; exit 1; }
    grep -q "Solid: restarted from" log.restart
)
/usr/bin/python3 - "$ref" "$killed" <<'PY'
import glob, os, sys
import numpy as np
ref, killed = sys.argv[1:3]
def load(path):
    return np.array([[float(x) for x in l.split()] for l in open(path)
                     if l.strip() and not l.startswith('#')])
ok = True
# Columns compared: every solid probe column; of the coupling log the time,
# dt, iterations and converged flag (exactly) and the interface force (r, z)
# and the largest interface velocity. Not compared: the final residual (a
# convergence measure below the 1e-6 tolerance), the swirl component of the
# force (zero but for round-off, 1e-20 N) and gclError (round-off, 1e-14)
checks = (("solidProbes/%s/solidProbes.dat", None, ()),
          ("fsi/%s/coupling.dat", (0, 1, 2, 4, 5, 6, 8), (0, 1, 2, 4)))
for name, cols, exact in checks:
    r = load(os.path.join(ref, "postProcessing", name % "0"))
    dirs = [d for d in glob.glob(os.path.join(killed, "postProcessing",
            name.split("/")[0], "*")) if os.path.basename(d) != "0"]
    assert len(dirs) == 1, dirs
    t0 = float(os.path.basename(dirs[0]))
    k = load(os.path.join(dirs[0], os.path.basename(name)))
    rr = r[r[:, 0] > t0*(1 + 1e-12)]
    assert rr.shape == k.shape, (rr.shape, k.shape)
    if cols is not None:
        rr, k = rr[:, cols], k[:, cols]
    scale = np.maximum(np.abs(rr).max(axis=0), 1e-300)
    diff = np.abs(rr - k)/scale
    print("%s: %d steps after the restart at %g s, largest difference %.3e "
          "of the column range (per column: %s), bitwise %s"
          % (os.path.basename(name), len(k), t0, diff.max(),
             " ".join("%.1e" % d for d in diff.max(axis=0)),
             np.array_equal(rr, k)))
    ok &= diff.max() <= 1e-10
    for c in exact:
        ok &= np.array_equal(rr[:, c], k[:, c])
    if "solidProbes" in name:
        # the pulse is in the cell over the compared window
        ok &= rr[:, 1].max() > 25e6
        print("probe peak pressure after the restart %.4g MPa"
              % (rr[:, 1].max()/1e6))
sys.exit(0 if ok else 1)
PY
