#!/bin/bash
# chainP2.sh QUEUE DIR (phase 2, on the merge of fix19j): chain.sh with the bases rebuilt on the merge under the prefix
# /tmp/adv53b- (prebuild.sh /tmp/adv53b-)
here=$(cd "$(dirname "$0")" && pwd); ADVPREFIX=${ADVPREFIX:-/tmp/adv53b-} exec bash $here/chain.sh "$@"
