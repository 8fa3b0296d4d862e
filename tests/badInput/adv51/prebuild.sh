#!/bin/bash
# prebuild.sh PREFIX: the bases this pass uses, built once under PREFIXadv47b (and adv35's under PREFIXadv35 ... adv48a)
# by the earlier passes' unchanged prebuild scripts called with my prefix: adv48a's (adv35-adv47b's: blastBase, indBase,
# bd, idn, ik, bd2, q), adv48b's (pbd, ibd), adv49b's (sbd, xbd, mbd), adv50b's (pwBase)
here=$(cd "$(dirname "$0")" && pwd); P=${1:-/tmp/adv51-}
bash $here/../adv48a/prebuild.sh $P && bash $here/../adv48b/prebuild.sh $P && bash $here/../adv49b/prebuild.sh $P && bash $here/../adv50b/prebuild.sh $P
