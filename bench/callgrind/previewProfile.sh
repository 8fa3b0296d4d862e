#!/bin/bash
# Instruction counts of the axisymmetric preview's time loop at G, one
# build against another (issue 18 item 2 in 2D, branch perf18: the mesh
# motion's share of a coupled pass, measured with a load-independent
# measure on a shared machine). The preview is prepared to END seconds
# (tests/blast/runPreview.sh DIR/case -noPlots -noVTK -noRun -endTime END:
# before the pulse reaches the cell, one coupling pass per step), copied
# once per build, and each copy's cellBlastFoam runs under
#   valgrind --tool=callgrind --collect-atstart=no
#       --toggle-collect=Foam::fluidSolidInteraction::step()
#       --toggle-collect=Foam::fluidSolidInteraction::setDeltaT()
#       --toggle-collect=Foam::fluidSolidInteraction::write(double)
# (as bench/callgrind/loopProfile.sh: the coupled step, time-step control
# and per-step output; start-up and field writes not counted), the builds
# at the same time. Prints per build the loop's Ir, the passes (the
# coupling log's iterations), and the inclusive Ir per pass of the mesh
# motion (fluidSolidInteraction::moveWall) and of its parts, the fluid
# pass (conservativeFluid::aleStep) and the solid's advance.
#
#   bench/callgrind/previewProfile.sh DIR END BUILD [BUILD...]
#       DIR    scratch folder (created; must not exist)
#       END    endTime [s] (2e-9: 70 steps)
#       BUILD  a copy of a worktree's platforms/linux64GccDPInt32Opt
#              (bin/cellBlastFoam and lib/)
#   NICENESS=N (default 10)
#   FROM="REF TIME"  instead of the start: a window of a finished run from
#              its write time TIME to END (REF a case of
#              tests/blast/runPreview.sh; its inputs, solid/, postProcessing
#              and TIME copied, startFrom latestTime, as
#              bench/blast/restartWindow.sh), e.g. the passage of the pulse
#              (FROM="REF 6.55e-08", END 6.628e-08: 23 steps of 2-3 passes)
#   EDIT=CMD   a shell command run in the last build's copy of the case
#              before its run (one build twice with an input changed, e.g.
#              EDIT="sed -i 's/timeScheme .*/&\n wedgeFaces cellPressure;/'
#              system/fvSolution" ... BUILD BUILD)
#
# Results: DIR/b<i>/axisymmetricPreview/cg.out, DIR/b<i>/inclusive.txt,
# DIR/table.txt. Takes about 50x the native run per build (70 steps: a
# few minutes each on an idle core).
set -euo pipefail
[ $# -ge 3 ] || { sed -n 2,38p "$0"; exit 1; }
dir=$1; end=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
builds=()
for b in "$@"
do
    [ -x "$b/bin/cellBlastFoam" ] && [ -d "$b/lib" ] || {
        echo "previewProfile.sh: $b has no bin/cellBlastFoam and lib/" >&2
        exit 1
    }
    builds+=("$(cd "$b" && pwd)")
done
[ ! -e "$dir" ] || { echo "previewProfile.sh: $dir exists" >&2; exit 1; }
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
if [ -n "${FROM:-}" ]
then
    read -r ref time <<< "$FROM"
    [ -d "$ref/$time" ] || { echo "previewProfile.sh: no $ref/$time" >&2; exit 1; }
    c=$dir/case/axisymmetricPreview
    mkdir -p "$c"
    for f in 0 0.orig constant system Allrun .allrunOptions solid \
        postProcessing "$time"
    do
        cp -a "$ref/$f" "$c/"
    done
    sed -i 's/^startFrom .*/startFrom       latestTime;/' "$c/system/controlDict"
    grep -q '^#sinclude "controlDict.allrun"' "$c/system/controlDict" \
        || printf '\n#sinclude "controlDict.allrun"\n' >> "$c/system/controlDict"
    echo "endTime $end;" >> "$c/system/controlDict.allrun"
    echo "window of $ref from $time to $end"
else
    "$root/tests/blast/runPreview.sh" "$dir/case" -noPlots -noVTK -noRun \
        -endTime "$end" > "$dir/prepare.log" 2>&1 \
        || { tail -20 "$dir/prepare.log"; exit 1; }
fi
. "$root/etc/bashrc"
echo "== $(date -u '+%F %H:%M UTC'), load $(cut -d' ' -f1-3 /proc/loadavg)"
pids=()
for i in "${!builds[@]}"
do
    mkdir -p "$dir/b$i"
    cp -a "$dir/case/axisymmetricPreview" "$dir/b$i/"
    if [ -n "${EDIT:-}" ] && [ "$i" -eq $((${#builds[@]} - 1)) ]
    then
        (cd "$dir/b$i/axisymmetricPreview" && eval "$EDIT") \
            || { echo "previewProfile.sh: EDIT failed" >&2; exit 1; }
        echo "build $i's case edited: $EDIT"
    fi
    (
        b=${builds[$i]}
        cd "$dir/b$i/axisymmetricPreview"
        PATH=$b/bin:$PATH LD_LIBRARY_PATH=$b/lib:$LD_LIBRARY_PATH \
        nice -n "${NICENESS:-10}" valgrind --tool=callgrind \
            --collect-atstart=no \
            "--toggle-collect=Foam::fluidSolidInteraction::step()" \
            "--toggle-collect=Foam::fluidSolidInteraction::setDeltaT()" \
            "--toggle-collect=Foam::fluidSolidInteraction::write(double)" \
            --callgrind-out-file="$PWD/cg.out" \
            cellBlastFoam > log.cellBlastFoam 2>&1
        callgrind_annotate --inclusive=yes --threshold=100 cg.out \
            > "$dir/b$i/inclusive.txt"
    ) &
    pids+=($!)
done
for p in "${pids[@]}"; do wait "$p"; done
echo "== done $(date -u '+%H:%M UTC'), load $(cut -d' ' -f1-3 /proc/loadavg)"
window=0
[ -z "${FROM:-}" ] || window=$time
/usr/bin/python3 - "$dir" "$window" "${builds[@]}" <<'PY' | tee "$dir/table.txt"
import glob, re, sys
# window: the start time's name (the window's coupling log is
# postProcessing/fsi/<start>/coupling.dat; 0 for a run from the start)
d, window, builds = sys.argv[1], sys.argv[2], sys.argv[3:]
parts = [
    ("loop (step, setDeltaT, write)", None),
    ("mesh motion (moveWall)", r"fluidSolidInteraction::moveWall\("),
    (" band update (bandMeshMotion::movePoints)", r"bandMeshMotion::movePoints\("),
    ("  geometry (updateGeometry)", r"bandMeshMotion::updateGeometry\("),
    ("   face::sweptVol", r"Foam::face::sweptVol\("),
    ("   face::centre", r"Foam::face::centre\("),
    ("  notify", r"bandMeshMotion::notify\("),
    (" interpolation (interfaceMotion::newPoints)", r"interfaceMotion::newPoints\("),
    ("fluid (conservativeFluid::aleStep)", r"conservativeFluid::aleStep\("),
    ("solid (solidDomain::advance)", r"solidDomain::advance\("),
]
def inclusive(path):
    total, rows = None, []
    for line in open(path, errors="replace"):
        m = re.match(r"\s*([\d,]+)\s+(\([^)]*\)\s+)?(\S.*)$", line)
        if not m:
            continue
        ir = int(m.group(1).replace(",", ""))
        if "PROGRAM TOTALS" in line:
            total = ir
        else:
            rows.append((ir, m.group(3)))
    return total, rows
print("%-46s" % "inclusive Ir per pass" + "".join("%14s" % ("build %d" % i)
      for i in range(len(builds))) + ("%10s" % "ratio" if len(builds) == 2 else ""))
cols = []
for i, b in enumerate(builds):
    total, rows = inclusive("%s/b%d/inclusive.txt" % (d, i))
    passes = 0
    for f in glob.glob("%s/b%d/axisymmetricPreview/postProcessing/fsi/%s/coupling.dat" % (d, i, window)):
        for l in open(f):
            if l.strip() and not l.startswith("#"):
                passes += int(l.split()[2])
    vals = {}
    for name, pat in parts:
        if pat is None:
            vals[name] = total
        else:
            # the largest inclusive count of a matching function (one
            # symbol; callgrind_annotate lists each once per object)
            hits = [ir for ir, fn in rows if re.search(pat, fn)]
            vals[name] = max(hits) if hits else 0
    cols.append((passes, vals))
    print("build %d: %s, %d passes" % (i, b, passes))
for name, _ in parts:
    line = "%-46s" % name
    for passes, vals in cols:
        line += "%14.4e" % (vals[name]/passes)
    if len(cols) == 2 and cols[0][1][name]:
        line += "%10.3f" % ((cols[1][1][name]/cols[1][0])
                            /(cols[0][1][name]/cols[0][0]))
    print(line)
for i, (passes, vals) in enumerate(cols):
    t = vals[parts[0][0]]
    print("build %d: mesh motion %.1f %%, fluid %.1f %%, solid %.1f %% of the loop"
          % (i, 100.0*vals[parts[1][0]]/t, 100.0*vals[parts[8][0]]/t,
             100.0*vals[parts[9][0]]/t))
PY
