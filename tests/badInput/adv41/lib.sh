# lib.sh (adv41): adv40's lib.sh (all helpers of adv35-adv40: blast/blastDone, pblast/pblastDone, latest, blastEnd, sums,
# changed, tryf, try, run, fatal, h5steps, xmfsteps, waitFor, lockOf, sameSeries, ...) with ADV defaulting to /tmp/adv41-B, plus:
#   wpDone [END]   a copy of the verification case waterPulseWall (rhoRiemannFoam, a `probes` function object) run to END (4e-8 s)
#   kept TEXT...   for each TEXT: the files of the case holding it, or GONE
#   nochange BEFORE  "results unchanged" or the files changed since the `sums` listing BEFORE
ADV=${ADV:-/tmp/adv41-B}
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv40/lib.sh"
wpDone() { cp -r "$ROOT/tutorials/verification/waterPulseWall" $W/wp; cd $W/wp; ./Allclean > /dev/null 2>&1; cp -r 0.orig 0; blockMesh > log.blockMesh 2>&1
  sed -i "s/^endTime .*/endTime ${1:-4e-8};/" system/controlDict; timeout -s KILL 200 rhoRiemannFoam > log.first 2>&1 || { echo "wpDone failed"; tail -3 log.first; }; }
kept() { local t w; for t in "$@"; do w=$(grep -rl --exclude='log.*' -- "$t" . 2>/dev/null | tr '\n' ' '); echo "   '$t': ${w:-GONE}"; done; }
nochange() { local c; c=$(changed "$1"); [ -z "${c// /}" ] && echo "   results unchanged" || echo "   changed: $c"; }
