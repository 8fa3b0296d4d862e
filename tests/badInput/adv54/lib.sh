# lib.sh (adv54): adv53's lib.sh (and through it every helper of adv35-adv53: bd, ind, idn, ik, pbd, blast, short,
# latest, rs, tryt, msg, say, sete, fsiSet, sig, md5all, same0/same1, mark/kept_, wp, wpEnd, wpDec, hdrDamage, iw ...)
# read unchanged from its folder. runOne.sh's ADV=<prefix>adv54 is mapped to <prefix>adv53, which adv53's lib.sh maps
# on to adv52 ... <prefix>adv47b, where every base lies (adv52's prebuild.sh, called with my prefix). At the case's
# exit $W is removed.
# Mine:
#   pi  [ARGS]    tutorials/indentation/plotIndentation.py on the current case (tryt 120), ARGS after the case
#   pk            the "C1,i" line of the last try.log (plotIndentation's table), squeezed
#   ok_ F         F's digest check by the package (resultDigest.check): "ok (uncovered from line N)" or the error
ADV=${ADV:-/tmp/adv54-adv54}; ADV=${ADV%adv54}adv53
here54_=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
. "$here54_/../adv53/lib.sh"
pi() { tryt 120 "${PL:-plotIndentation.py} $*" /usr/bin/python3 "$ROOT/tutorials/indentation/plotIndentation.py" . "$@"; }
pk() { grep -a 'C1,i\|F_B\|C1,r' $W/try.log | head -3 | tr -s ' ' | tr '\n' '|' | cut -c1-300; }
ok_() { /usr/bin/python3 - "$1" <<'P'
import sys
from neuronFsi import resultDigest
try:
    r = resultDigest.check(sys.argv[1]); print("   check %s: ok, uncovered from line %s" % (sys.argv[1], r))
except Exception as e:
    print("   check %s: %s: %s" % (sys.argv[1], type(e).__name__, str(e)[:300]))
P
}
#   p8 / q8       bd (the finished 2-ns preview) / bd2 (its pulse doubled) restarted to 8e-9 (the pulse then reaches the
#                 probes), p8 with planeWave's reference written; bases p8Base, q8Base built once (mkBase_), cd to a copy
p8Done_() { bd; latest; blastEnd 8e-9 1e-9; rm -f .runLock; cellBlastFoam > log.cellBlastFoam 2>&1 || { echo "p8: run failed"; tail -3 log.cellBlastFoam; }; planeWave -case . > log.planeWave 2>&1 || { echo "p8: planeWave rc $?"; tail -2 log.planeWave; }; }
q8Done_() { bd2; latest; blastEnd 8e-9 1e-9; rm -f .runLock; cellBlastFoam > log.cellBlastFoam 2>&1 || { echo "q8: run failed"; tail -3 log.cellBlastFoam; }; mv $W/blast2 $W/blast; }
p8() { mkBase_ p8Base p8Done_ blast; cp -a $ADV/p8Base $W/p8; cd $W/p8; }
q8() { mkBase_ q8Base q8Done_ blast; cp -a $ADV/q8Base $W/q8; cd $W/q8; }
