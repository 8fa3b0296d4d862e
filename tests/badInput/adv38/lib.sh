# lib.sh (adv38): adv37's lib.sh (adv35/adv36/adv37 base cases and helpers: ind/indDone/blast/blastDone/sod/sodDone,
# pblast/pblastDone, setd, blastEnd, latest, committed, killAfter, indKilled, try, each, snap/gone, study, cal, prev/PREV,
# inDir/killIn, run, fatal) with ADV defaulting to /tmp/adv38x, plus:
#   waitFor N CMD...   polls CMD every 0.05 s for at most N s (0 when it became true)
#   lockOf             the case's .runLock, one line
#   indAllrun          a copy of tutorials/indentation/averageCell with the smoke protocol (mesh not made), cd there
ADV=${ADV:-/tmp/adv38x}
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv37/lib.sh"
waitFor() { local n=$1 i=0; shift; until "$@" 2>/dev/null; do sleep 0.05; i=$((i+1)); [ $i -ge $((n*20)) ] && return 1; done; return 0; }
lockOf() { [ -f .runLock ] && tr '\n' ';' < .runLock | cut -c1-300 || echo "(no lock)"; }
indAllrun() { cp -r "$ROOT/tutorials/indentation/averageCell" "$W/ia"; cd "$W/ia"; /usr/bin/python3 "$ROOT/tests/lib/setProtocol.py" constant/indenterProperties --smoke; }
#   sameSeries REF   the four blast logs (fsi/coupling.dat, solidProbes, interfaceMaxima, fluidProbes/p) joined over their restart
#                    segments (neuronFsi.postProcessing.series) here and in case REF: "same"/"DIFF" per log, exact
sameSeries() { PYTHONPATH=$ROOT/src/python /usr/bin/python3 - "$1" <<'P'
import sys, numpy as np
from neuronFsi.postProcessing import series
for log in ("fsi/coupling.dat", "solidProbes/solidProbes.dat", "solidInterfaces/interfaceMaxima.dat", "fluidProbes/p"):
    try:
        a, b = series(".", log), series(sys.argv[1], log)
        print("%s: %s (%d rows here, %d in the reference)" % (log, "same" if a.shape == b.shape and np.array_equal(a, b) else "DIFF", len(a), len(b)))
    except Exception as e:
        print("%s: error %s" % (log, e))
P
}
