#!/bin/bash
# t29: solidToFoam on a text file
. "$(dirname "$0")/../lib.sh"
indDone; solidToFoam constant/indenterProperties 2>&1 | grep -A3 "FATAL\|rror" | head -5; echo "rc=${PIPESTATUS[0]}"
