#!/bin/bash
# prebuild.sh PREFIX: adv45's prebuild.sh (adv44's) for adv46a: builds the base cases (adv35's lib.sh: indBase, blastBase) once under
# PREFIXadv35, copies them to every other pass's PREFIXPASS (the same build, the same inputs), then sources each pass's lib.sh
# (each from its pass's folder) so that nothing is built while cases run two at a time
here=$(cd "$(dirname "$0")" && pwd); cd $here/..; P=${1:-/tmp/adv46a-}
for p in adv35 adv36 adv37 adv38 adv39 adv40 adv41 adv42 adv43 adv44 adv45 adv46a; do l=$p/lib.sh; [ -f $l ] || continue
  [ $p != adv35 ] && [ ! -e $P$p ] && cp -a ${P}adv35 $P$p && rm -rf $P$p/w.*
  ADV=$P$p nice -n 10 bash -c ". $l; echo $p: \$(ls \$ADV | grep -v '^w\.' | tr '\n' ' '); rmdir \$W"; done
