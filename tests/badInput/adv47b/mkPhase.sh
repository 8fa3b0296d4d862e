#!/bin/bash
# mkPhase.sh FILE...: one verdict line per case, the last of the files given (a case re-run after its first run was n/r or
# corrected keeps its later verdict, marked with the file's run name), sorted by id
for f in "$@"; do r=$(basename $f .txt); r=${r#verdicts}; sed "s/^\(f[0-9]*\) \+\([^ ]*\) \+/\1 \2 ($r) /" $f; done | awk '{l[$1]=$0} END {for (k in l) print l[k]}' | sort
