#!/bin/bash
# prebuild.sh PREFIX (adv48a): adv47a's prebuild.sh with PREFIX (adv35's indBase/blastBase for every pass, adv46b's bdBase,
# idBase, ikBase), then adv47b's bases (its prebuild.sh: bd2Base, qBase; bd/idn/ik copied first, not rebuilt) under
# PREFIXadv47b, and every base copied to PREFIXadv48a for adv48a's own cases
here=$(cd "$(dirname "$0")" && pwd); P=${1:-/tmp/adv48a-}
bash $here/../adv47a/prebuild.sh $P
mkdir -p ${P}adv47b; for b in bdBase idBase ikBase; do [ -e ${P}adv47b/$b ] || cp -a ${P}adv46b/$b ${P}adv47b/$b; done
bash $here/../adv47b/prebuild.sh $P
mkdir -p ${P}adv48a; for b in indBase blastBase bdBase idBase ikBase bd2Base qBase; do [ -e ${P}adv48a/$b ] || cp -a ${P}adv47b/$b ${P}adv48a/$b; done; ls ${P}adv48a
