#!/bin/bash
# todo.sh DIR: the outputs of out/DIR still to judge: finished, not in verdicts.py, and not equal to their latest judged output
cd "$(dirname "$0")"; python3 compare.py $1 | grep -v '(running)' | while read k rest; do
  grep -q "^ \"$k\":" verdicts.py && continue; case "$rest" in "same as"*) [[ "$rest" != *NOT* ]] && continue;; esac; echo "$k $rest"; done
