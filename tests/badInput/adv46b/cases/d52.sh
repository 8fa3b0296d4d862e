#!/bin/bash
# d52 (class 6, a pulseStudy grid of 1e6 points: overpressure and duration of 1000 values each): refused before anything (a limit on the grid) or, if it starts, it must not create 1e6 folders or hang building them; 60 s, max RSS, folders created.
. "$(dirname "$0")/../lib.sh"
study; python3 - system/pulseStudyDict <<P
import re,sys; p=sys.argv[1]; t=open(p).read()
t=re.sub(r"^overpressure .*$", "overpressure (" + " ".join("%de6" % (i+1) for i in range(1000)) + ");", t, flags=re.M)
t=re.sub(r"^duration .*$", "duration (" + " ".join("%de-12" % (1000+i) for i in range(1000)) + ");", t, flags=re.M); open(p,"w").write(t)
P
/usr/bin/time -f "%M" -o ../rss timeout -s KILL 60 pulseStudy > $W/try.log 2>&1; echo "rc=$? maxRSS $(tail -1 ../rss) kB | $(grep -a -m2 -i "error\|refus\|limit\|points" $W/try.log | cut -c1-300 | tr "\n" " ")"; echo "   folders: $(find . -type d | wc -l), processes left in the study: $(inDir $W | cut -c1-200)"; killIn $W
