#!/bin/bash
# prebuild.sh PREFIX: builds the base cases once under PREFIXadv46b by sourcing this pass's lib.sh (adv35's indBase,
# blastBase) and adv46b's bases (bdBase, idBase, ikBase: lib.sh), so that nothing is built while cases run two at a time
here=$(cd "$(dirname "$0")" && pwd); P=${1:-/tmp/adv46b-}
ADV=${P}adv46b nice -n 10 bash -c ". $here/lib.sh; bd; idn; ik; echo adv46b: \$(ls \$ADV | grep -v '^w\.' | tr '\n' ' '); rm -rf \$W"
