#!/bin/bash
# d62 (class 4+6, an #include of a device or a FIFO in indenterProperties: #include "/dev/zero", then #include of a FIFO nobody writes, cellIndentationFoam and cellMesh -dict, 40 s each): refused at once naming the include; never HANG.
. "$(dirname "$0")/../lib.sh"
ind; cp constant/indenterProperties ../ip; mkfifo $W/fifo
for f in /dev/zero $W/fifo; do cp ../ip constant/indenterProperties; echo "#include \"$f\"" >> constant/indenterProperties
  /usr/bin/time -f "%M" -o ../rss timeout -s KILL 40 cellIndentationFoam > $W/try.log 2>&1; echo "[$f] cellIndentationFoam: rc=$? maxRSS $(tail -1 ../rss) kB | $(grep -a -m1 -A2 "FATAL\|rror" $W/try.log | grep -v "^ *$" | head -3 | tr "\n" " " | cut -c1-300)"; done
cp ../ip constant/indenterProperties; for f in /dev/zero $W/fifo; do /usr/bin/time -f "%M" -o ../rss timeout -s KILL 40 cellMesh -dict $f > $W/try.log 2>&1; echo "[$f] cellMesh -dict: rc=$? maxRSS $(tail -1 ../rss) kB | $(grep -a -m1 -A2 "FATAL\|rror" $W/try.log | grep -v "^ *$" | head -3 | tr "\n" " " | cut -c1-300)"; done
