# lib.sh (adv44): adv43's lib.sh (tests/badInput/adv43: all helpers of adv35-adv43: ind/indDone, indKilled, blast/blastDone,
# pblast/pblastDone, blastEnd, latest, restart0, sums, changed, nochange, kept, tryf, try, run, fatal, waitFor, sameSeries,
# study, setStudy, cal, prev/PREV, wpDone, blastRef, cmpRef, killAt, marks, flip, h5same, nul, ...) with ADV defaulting to
# /tmp/adv44-adv44, plus:
#   where TEXT...    for each TEXT: "kept (files)" or "GONE", searched in the whole work folder $W (not only the case)
ADV=${ADV:-/tmp/adv44-adv44}
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv43/lib.sh"
where() { local t w; for t in "$@"; do w=$(grep -rl --exclude='log.*' -- "$t" $W 2>/dev/null | sed "s|$W/||" | tr '\n' ' '); echo "   '$t': ${w:-GONE}"; done; }
