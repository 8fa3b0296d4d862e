# lib.sh (adv48b): adv47b's lib.sh (tests/badInput/adv47b, and through it every helper of adv35-adv47b: bd, rs, bd2, idn,
# ik, q, blast/blastDone, blastEnd, latest, sums, changed, nochange, kept, where, tryf, tryt, try, each, run, fatal, waitFor,
# sameSeries, cmpRef, closeTo, study, setStudy, cal, prev/PREV, iblast/IW/iEnd, pblast/pblastDone, flip, nul, h5same,
# h5steps, xmfsteps, marks, lockOf, ro, tiny, sete, dupe, inDir, killIn, after, cont, forceOk ...) with its bases: the
# bases are built by adv47b's prebuild.sh called with this pass's prefix (`bash ../adv47b/prebuild.sh /tmp/adv48b-`:
# under /tmp/adv48b-adv47b), so ADV is that folder (runOne.sh's ADV=<prefix>adv48b is mapped to <prefix>adv47b); plus:
#   pbd       a finished 2-rank blast preview (pblastDone: processor0/1 hold 1e-09, 2e-09), cd there (base pbdBase)
#   ibd       the inflow preview (iblast: planeWaveInflow top, -Z 40e-6 -inflow 20e-6) run to 2e-9, cd there (base ibdBase)
#   short     endTime 2e-11 and writeInterval 1e-11 in a blast copy (an accepted input runs a few steps only)
#   nLines F  rows of F that are not comments
ADV=${ADV:-/tmp/adv48b-adv48b}; ADV=${ADV%adv48b}adv47b
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv47b/lib.sh"
pbd() { mkBase_ pbdBase pblastDone blast; cp -a $ADV/pbdBase $W/pblast; cd $W/pblast; }
ibdDone_() { iblast 2e-9; mv $W/c $W/blast; cd $W/blast; cellBlastFoam > log.first 2>&1 || { echo "ibdDone failed"; tail -3 log.first; }; }
ibd() { mkBase_ ibdBase ibdDone_ blast; cp -a $ADV/ibdBase $W/iblast; cd $W/iblast; }
short() { blastEnd 2e-11 1e-11; }
nLines() { grep -vc '^#' "$1" 2>/dev/null; }
