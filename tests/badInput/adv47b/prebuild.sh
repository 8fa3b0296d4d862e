#!/bin/bash
# prebuild.sh PREFIX: builds the base cases once under PREFIXadv47b (adv35's indBase/blastBase, adv46b's bdBase, idBase,
# ikBase and adv47b's bd2Base, qBase: lib.sh), so that nothing is built while the cases run two at a time
here=$(cd "$(dirname "$0")" && pwd); P=${1:-/tmp/adv47b-}
ADV=${P}adv47b nice -n 10 bash -c ". $here/lib.sh; bd; idn; ik; bd2; q; echo adv47b: \$(ls \$ADV | grep -v '^w\.' | tr '\n' ' '); rm -rf \$W"
