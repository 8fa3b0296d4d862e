# lib.sh (adv53): adv52's lib.sh (and through it every helper of adv35-adv52: bd, idn, ik, pbd, q, sb, blast, short,
# latest, rs, tryt, msg, sete, subset, fsiSet, fset, setb, sig, hdr0/hdr, md5all, same0/same1, mark/kept_, inDir,
# killIn, pwd0, iw ...) read unchanged from its folder. runOne.sh's ADV=<prefix>adv53 is mapped to <prefix>adv52,
# which adv52's lib.sh maps on to adv51 ... <prefix>adv47b, where every base lies (adv52's prebuild.sh, called with
# my prefix). At the case's exit $W is removed.
# Mine:
#   wp [END]      waterPulseWall (rhoRiemannFoam, probes) run to END (default 4e-8 s) in $W/wp, cd there (adv41's wpDone)
#   wpEnd END     endTime END in its system/controlDict
#   say [N]       the first N (4) lines of the last tryt's error block, unwrapped (msg with a default of 4)
ADV=${ADV:-/tmp/adv53-adv53}; ADV=${ADV%adv53}adv52
here53_=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
. "$here53_/../adv52/lib.sh"
wp() { wpDone "${1:-4e-8}"; }
wpEnd() { sed -i "s/^endTime .*/endTime $1;/" system/controlDict; }
say() { msg ${1:-4}; }
#   wpDec          a decomposeParDict of 2 ranks (simple 2 1 1) in system/, decomposePar run (log.decomposePar)
#   hdrDamage F    the first 8 bytes of F overwritten ("CORRUPT!": its FoamFile header no longer readable)
wpDec() { printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmethod simple;\nsimpleCoeffs { n (2 1 1); delta 0.001; }\n' > system/decomposeParDict; decomposePar -force > log.decomposePar 2>&1 || { echo "wpDec: decomposePar failed"; tail -3 log.decomposePar; }; }
hdrDamage() { printf 'CORRUPT!' | dd of="$1" bs=1 seek=0 conv=notrunc status=none; echo "   $1: first 8 bytes overwritten"; }
