#!/bin/bash
# A window of a blast preview run recomputed from one of its write times
# with this build, and its rows compared with the run's own (issue 18 item
# 5, branch prev18: a kernel change that should keep the results' bits,
# checked where the pulse passes the cell and the coupling takes several
# passes per step; not a test).
#
#   bench/blast/restartWindow.sh REF TIME END DIR
#       REF   a finished or running case of tests/blast/runPreview.sh
#             (e.g. /tmp/base/axisymmetricPreview), run with another build
#       TIME  one of REF's write times (its directory name, e.g. 6.55e-08),
#             or 0: a run from the start (REF's inputs and 0/ only)
#       END   endTime of the window [s]
#       DIR   scratch folder (created; must not exist)
#
# DIR/axisymmetricPreview: REF's inputs, postProcessing, solid/ and TIME,
# startFrom latestTime, endTime END; cellBlastFoam of this environment
# (etc/bashrc) runs the window; then for each of the coupling log, the
# solid probes, the interface maxima and the water probes: the rows of the
# window and how many of them are byte-identical to REF's row of the same
# time; if END is also one of REF's write times, every file of that time
# directory against REF's (cmp). Prints those counts; exit 1 if a row or
# a file differs.
set -euo pipefail
[ $# -eq 4 ] || { sed -n 2,20p "$0"; exit 1; }
ref=$1; time=$2; end=$3; dir=$4
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
[ -d "$ref/$time" ] || { echo "restartWindow.sh: no $ref/$time" >&2; exit 1; }
[ ! -e "$dir" ] || { echo "restartWindow.sh: $dir exists" >&2; exit 1; }
c=$dir/axisymmetricPreview
mkdir -p "$c"
copied=(0 0.orig constant system Allrun .allrunOptions)
[ "$time" = 0 ] || copied+=(solid postProcessing "$time")
for f in "${copied[@]}"
do
    cp -a "$ref/$f" "$c/"
done
cd "$c"
# (sed, not foamDictionary: that writes the dictionary with its #sinclude
# of controlDict.allrun expanded, which the endTime below goes to)
sed -i 's/^startFrom .*/startFrom       latestTime;/' system/controlDict
grep -q '^#sinclude "controlDict.allrun"' system/controlDict \
    || printf '\n#sinclude "controlDict.allrun"\n' >> system/controlDict
echo "endTime $end;" >> system/controlDict.allrun
echo "== $(date -u '+%F %H:%M UTC'), $(command -v cellBlastFoam), load $(cut -d' ' -f1-3 /proc/loadavg)"
nice -n "${NICENESS:-5}" cellBlastFoam > log.cellBlastFoam 2>&1 \
    || { tail -20 log.cellBlastFoam; exit 1; }
/usr/bin/python3 - "$ref" "$time" "$end" <<'PY'
import filecmp, os, sys
ref, time, end = sys.argv[1:]
bad = 0
for log in ("fsi/%s/coupling.dat", "solidProbes/%s/solidProbes.dat",
            "solidInterfaces/%s/interfaceMaxima.dat", "fluidProbes/%s/p"):
    def rows(path):
        return [l for l in open(path) if l.strip() and not l.startswith("#")]
    new = rows("postProcessing/" + log % time)
    old = {}
    for l in rows(ref + "/postProcessing/" + log % "0"):
        old[l.split()[0]] = l
    same = sum(1 for l in new if old.get(l.split()[0]) == l)
    bad += len(new) - same
    print("%s: %d rows, %d byte-identical to REF's" % (log % time, len(new),
                                                      same))
if os.path.isdir(os.path.join(ref, end)) and os.path.isdir(end):
    files = sorted(os.path.relpath(os.path.join(d, f), end)
                   for d, _, fs in os.walk(end) for f in fs)
    differ = [f for f in files
              if not os.path.isfile(os.path.join(ref, end, f))
              or not filecmp.cmp(os.path.join(ref, end, f),
                                 os.path.join(end, f), shallow=False)]
    bad += len(differ)
    print("%s/: %d files, %d byte-identical to REF's%s"
          % (end, len(files), len(files) - len(differ),
             (" (differ: %s)" % " ".join(differ)) if differ else ""))
sys.exit(1 if bad else 0)
PY
grep "CPU time of the time loop" log.cellBlastFoam
