#!/bin/bash
# w67: calibrateCell -work pointing at an existing folder holding a user's file (and at the case itself): the user's file kept? (killed after 20 s)
. "$(dirname "$0")/../lib.sh"
cal; mkdir -p ../mywork; echo "my notes" > ../mywork/notes.txt; timeout -s TERM 20 calibrateCell -case . -nProcs 1 -work ../mywork > log.1 2>&1; echo "rc=$?"; fatal log.1 3; ls ../mywork | head; cat ../mywork/notes.txt 2>/dev/null || echo "notes.txt GONE"
timeout -s TERM 20 calibrateCell -case . -nProcs 1 -work . > log.2 2>&1; echo "work=case rc=$?"; fatal log.2 3; ls | tr '\n' ' '
