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
