# lib.sh (adv43): adv42's lib.sh (tests/badInput/adv42: all helpers of adv35-adv42: ind/indDone, indKilled, blast/blastDone,
# pblast/pblastDone, blastEnd, latest, sums, changed, nochange, kept, tryf, try, run, fatal, waitFor, sameSeries, study,
# wpDone, blastRef, cmpRef, killAt, ...) with ADV defaulting to /tmp/adv43-adv43, plus:
#   marks TEXT       the commit markers (*/.writeCommitted, processor*/*/.writeCommitted) naming TEXT
#   restart0         startFrom startTime (for -overwrite from 0)
ADV=${ADV:-/tmp/adv43-adv43}
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv42/lib.sh"
marks() { echo "   markers naming '$1': $(grep -a -l -- "$1" */.writeCommitted processor*/*/.writeCommitted 2>/dev/null | tr '\n' ' ')"; }
restart0() { sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; }
