#!/bin/bash
# prebuild.sh PREFIX: the bases this pass uses, built once under PREFIXadv47b before the cases run two at a time: adv46b's
# bd and idn, adv47b's q (their lib.sh functions, through mine), and mine: pwBase (lib.sh pwd0)
here=$(cd "$(dirname "$0")" && pwd); P=${1:-/tmp/adv50b-}
ADV=${P}adv50b nice -n 10 bash -c ". $here/lib.sh; bd; idn; q; pwd0; echo adv50b: \$(ls \$ADV | grep -v '^w\.' | tr '\n' ' ')"
