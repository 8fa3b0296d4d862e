#!/bin/bash
# d30 (class 3, two calibrateCell at once with the same -work folder): the second refused (the folder is the first one's and in use), never removing or sharing the live folder; the first not disturbed.
. "$(dirname "$0")/../lib.sh"
cal; calibrateCell -work $W/work > ../l1 2>&1 & p=$!; waitFor 60 test -d $W/work; sleep 3; echo "   work before: $(ls $W/work | head -5 | tr "\n" " ")"
tryt 60 "second calibrateCell, same -work" calibrateCell -work $W/work; echo "   work after: $(ls $W/work 2>&1 | head -5 | tr "\n" " ")"; sleep 5; echo "   first still running: $(kill -0 $p 2>/dev/null && echo yes || echo no) $(tail -2 ../l1 | cut -c1-150 | tr "\n" " ")"; kill -TERM $p; wait $p
