#!/bin/bash
# t25: paperFigures -results nonexisting folder
. "$(dirname "$0")/../lib.sh"
cd "$W"; cp -r "$ROOT/tutorials/paper" paper; cd paper; timeout 120 paperFigures -results /nonexistent/x -noRun 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"
