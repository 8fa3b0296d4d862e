#!/bin/bash
# t26: paperFigures -output pointing at an existing user file
. "$(dirname "$0")/../lib.sh"
cd "$W"; cp -r "$ROOT/tutorials/paper" paper; cd paper; echo "user data" > mine.txt; timeout 120 paperFigures -output mine.txt -noRun 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"; cat mine.txt
