#!/bin/bash
# prebuild.sh PREFIX: the bases of every pass once: adv46a's prebuild.sh (adv35's indBase, blastBase under PREFIXadv35,
# copied to every pass adv36-adv46a), then the same copy for adv46b and adv47a and adv46b's own bases (bdBase, idBase,
# ikBase: adv46b's prebuild.sh) built once under PREFIXadv46b and copied to PREFIXadv47a
here=$(cd "$(dirname "$0")" && pwd); P=${1:-/tmp/adv47a-}
bash $here/../adv46a/prebuild.sh $P
for p in adv46b adv47a; do [ -e $P$p ] || { cp -a ${P}adv35 $P$p && rm -rf $P$p/w.*; }; done
bash $here/../adv46b/prebuild.sh $P
for b in bdBase idBase ikBase; do [ -e ${P}adv47a/$b ] || cp -a ${P}adv46b/$b ${P}adv47a/$b; done; ls ${P}adv47a
