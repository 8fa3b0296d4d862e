#!/bin/bash
# d34 (class 3, two pulseStudy runs at once on one study folder, a one-point grid): one refused, or both finish with one consistent record and map (docs: "two pulseStudy runs on one case at once are not prevented"); judged on the outputs.
. "$(dirname "$0")/../lib.sh"
study; pulseStudy > ../l1 2>&1 & p1=$!; sleep 5; pulseStudy > ../l2 2>&1 & p2=$!; wait $p1; r1=$?; wait $p2; r2=$?
echo "   first rc=$r1: $(grep -a -i "error\|refus\|Traceback" ../l1 | head -2 | cut -c1-200 | tr "\n" " ")"; echo "   second rc=$r2: $(grep -a -i "error\|refus\|Traceback" ../l2 | head -2 | cut -c1-200 | tr "\n" " ")"
find . -name result.json | head; find . -maxdepth 3 -type d | grep -v "/points/.*/case/" | head -20 | tr "\n" " "
