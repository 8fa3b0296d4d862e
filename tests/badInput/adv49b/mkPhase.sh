#!/bin/bash
# mkPhase.sh FILE...: adv47b's mkPhase.sh for the ids of this pass (iNN): one verdict line per case, the last of the files
# given winning, sorted by id
for f in "$@"; do r=$(basename $f .txt); r=${r#verdicts}; grep -v '^#' $f; done | awk 'NF{l[$1]=$0} END {for (k in l) print l[k]}' | sort
