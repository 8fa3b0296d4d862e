#!/bin/bash
# chainP2.sh QUEUE DIR (phase 2, on the merge of fix19i): chain.sh with the bases rebuilt on the merge under the prefix
# /tmp/adv52b- (prebuild.sh /tmp/adv52b-; the phase-1 bases were made by main's Allruns and solvers)
here=$(cd "$(dirname "$0")" && pwd); ADVPREFIX=${ADVPREFIX:-/tmp/adv52b-} exec bash $here/chain.sh "$@"
