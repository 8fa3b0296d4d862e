#!/bin/bash
# d52 (class 6, a pulseStudy grid of 1e6 points: overpressure and duration of 1000 values each): refused before anything (a limit on the grid) or, if it starts, it must not create 1e6 folders or hang building them; 100 s, its RSS every 30 s (corrected after the first run: its output was block-buffered and lost at the kill), folders created.
. "$(dirname "$0")/../lib.sh"
study; python3 - system/pulseStudyDict <<P
import re,sys; p=sys.argv[1]; t=open(p).read()
t=re.sub(r"^overpressure .*$", "overpressure (" + " ".join("%de6" % (i+1) for i in range(1000)) + ");", t, flags=re.M)
t=re.sub(r"^duration .*$", "duration (" + " ".join("%de-12" % (1000+i) for i in range(1000)) + ");", t, flags=re.M); open(p,"w").write(t)
P
PYTHONUNBUFFERED=1 timeout -s KILL 100 pulseStudy > $W/try.log 2>&1 & p=$!; for s in 30 60 90; do sleep 30; echo "   after $s s: pulseStudy RSS $(for q in $(pgrep -f pulseStudy.py); do readlink /proc/$q/cwd | grep -q "^$W" && ps -o rss= -p $q; done | head -1) kB, running: $(kill -0 $p 2>/dev/null && echo yes || echo no)"; done; wait $p; echo "rc=$? | $(grep -a -m3 -i "error\|refus\|limit\|points\|done" $W/try.log | cut -c1-200 | tr "\n" " ")"; echo "   folders: $(find . -type d | wc -l), processes left in the study: $(inDir $W | cut -c1-200)"; killIn $W
