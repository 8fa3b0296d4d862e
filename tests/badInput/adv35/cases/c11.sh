#!/bin/bash
# c11: a .runLock naming a live process (a sleep) with executable cellIndentationFoam and this case
. "$(dirname "$0")/../lib.sh"
ind; sleep 30 & sp=$!
printf 'pid %s\nhost %s\nexecutable cellIndentationFoam\nstarted 2026-12-04T16:00:00\ncase %s\n' $sp $(hostname) "$PWD" > .runLock
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror\|lock" log.run | head -8; tail -1 log.run; echo "rc=$rc"; kill $sp
