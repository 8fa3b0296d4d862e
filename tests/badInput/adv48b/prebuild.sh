#!/bin/bash
# prebuild.sh PREFIX: adv47b's prebuild.sh with this pass's prefix (its bases under PREFIXadv47b: bdBase, idBase, ikBase,
# bd2Base, qBase), then this pass's own bases in the same folder (pbdBase, ibdBase: lib.sh)
here=$(cd "$(dirname "$0")" && pwd); P=${1:-/tmp/adv48b-}
bash $here/../adv47b/prebuild.sh $P
ADV=${P}adv48b nice -n 10 bash -c ". $here/lib.sh; pbd; ibd; echo adv48b: \$(ls \$ADV | grep -v '^w\.' | tr '\n' ' '); rm -rf \$W"
