#!/bin/bash
# prebuild.sh PREFIX: the bases this pass uses, built once under PREFIXadv47b before the cases run two at a time: adv46b's
# bd, idn, ik and adv48b's pbd (their lib.sh functions, through mine; not adv47b's bd2 and q, which no case of mine uses),
# and mine: sbd, xbd, mbd (lib.sh)
here=$(cd "$(dirname "$0")" && pwd); P=${1:-/tmp/adv49b-}
ADV=${P}adv49b nice -n 10 bash -c ". $here/lib.sh; bd; idn; ik; pbd; sbd; xbd; mbd; echo adv49b: \$(ls \$ADV | grep -v '^w\.' | tr '\n' ' '); rm -rf \$W"
