#!/bin/bash
# d61 (class 4+6, the solid mesh file a device or a FIFO: constant/solidProperties mesh/file "/dev/zero", then a FIFO nobody writes, cellIndentationFoam, 40 s each): refused at once naming the entry and what the file is; never reading without end (HANG) or allocating until killed.
. "$(dirname "$0")/../lib.sh"
ind; cp constant/solidProperties ../sp; mkfifo $W/fifo
for f in /dev/zero $W/fifo; do cp ../sp constant/solidProperties; sed -i "s|file        \"constant/cell.msh\";|file        \"$f\";|" constant/solidProperties; grep -c "$f" constant/solidProperties
  /usr/bin/time -f "%M" -o ../rss timeout -s KILL 40 cellIndentationFoam > $W/try.log 2>&1; echo "[$f]: rc=$? maxRSS $(tail -1 ../rss) kB | $(grep -a -m1 -A2 "FATAL\|rror" $W/try.log | grep -v "^ *$" | head -3 | tr "\n" " " | cut -c1-300)"; done
