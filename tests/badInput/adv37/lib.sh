# lib.sh (adv37): adv36's lib.sh (adv35's base cases ind/indDone/blast/blastDone/sod/sodDone, setd, sums; blastEnd,
# contents, lost) plus:
#   run N CMD...     CMD under `timeout -s KILL N`, prints "rc=<exit>" after it (137 = killed by the timeout: HANG if N is generous)
#   fatal LOG [N]    the first N (6) lines from the first FATAL/Error/Traceback of LOG
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv36/lib.sh"
run() { local n=$1; shift; timeout -s KILL "$n" "$@"; local rc=$?; echo "rc=$rc"; return $rc; }
fatal() { grep -a -m1 -A${2:-6} -i 'FATAL\|^Error\|error:\|Traceback\|refus\|cannot' "$1" | grep -av '^ *$' | head -${2:-6} | cut -c1-300; }
#   pblast           a blast copy split in two ranks at y = 4 um (manual decomposition, tests/lib/splitAtPlane.sh), decomposed
#   splitY Y         splitAtPlane . y Y, and the #sinclude of controlDict.allrun put back (foamDictionary -set drops it)
#   pblastDone       the same, run on 2 ranks to its end
. "$ROOT/tests/lib/splitAtPlane.sh"
splitY() { splitAtPlane . y $1; grep -q "controlDict.allrun" system/controlDict || echo '#sinclude "controlDict.allrun"' >> system/controlDict; }
pblast() { blast; splitY 4e-6; decomposePar > log.decompose 2>&1 || { echo "decomposePar failed"; tail -3 log.decompose; }; }
pblastDone() { pblast; mpirun -np 2 cellBlastFoam -parallel > log.first 2>&1 || { echo "pblastDone failed"; tail -3 log.first; }; }
#   latest           startFrom latestTime in system/controlDict (sed: foamDictionary -set would drop its #sinclude of controlDict.allrun)
#   committed        the number of committed time directories of processor1 (or of the case, serial)
latest() { sed -i 's/^startFrom .*/startFrom latestTime;/' system/controlDict; }
committed() { if [ -d processor1 ]; then ls -d processor1/*/.writeCommitted 2>/dev/null | wc -l; else ls -d */.writeCommitted 2>/dev/null | wc -l; fi; }
#   killAfter N PID [S]  waits for N committed writes (at most 60 s), then S s more (default: random in [0, 0.3)), then SIGKILLs PID's children and PID
killAfter() { local i=0; until [ "$(committed)" -ge "$1" ] || [ $i -ge 600 ]; do sleep 0.1; i=$((i+1)); done; local s=${3:-$(/usr/bin/python3 -c "import random;print(round(random.uniform(0,0.3),3))")}; sleep $s; pkill -KILL -P $2; kill -KILL $2 2>/dev/null; wait $2 2>/dev/null; echo "killed after $(committed) commits (+$s s)"; }
#   indKilled S      a fresh indentation case with 10x finer depth steps (maxDepthIncrement 0.01 um), SIGKILLed S s after its first checkpoint, startFrom latestTime
indKilled() { ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; cellIndentationFoam > log.first 2>&1 & local p=$! i=0; until [ -f postProcessing/indentation/restart.h5 ] || [ $i -ge 300 ]; do sleep 0.1; i=$((i+1)); done; sleep $1; kill -KILL $p; wait $p 2>/dev/null; latest; echo "killed $1 s after the first checkpoint: $(ls postProcessing/indentation | tr '\n' ' ') force rows $(grep -vc '^#' postProcessing/indentation/force.dat)"; }
#   try LABEL CMD... runs CMD (60 s timeout), prints "LABEL: rc=<exit> | <first error line>"
try() { local l=$1; shift; timeout -s KILL 60 "$@" > $W/try.log 2>&1; local rc=$?; echo "$l: rc=$rc | $(grep -a -m1 -A2 -i 'FATAL\|error\|refus\|invalid\|cannot\|Traceback\|not ' $W/try.log | grep -av '^ *$\|^-->' | head -2 | tr '\n' ' ' | cut -c1-260)"; }
#   snap FILE / gone FILE   as contents/lost, with the file names: the earlier files whose content is found nowhere in the case now
snap() { find . -type f ! -path './system/*' ! -path './constant/*' ! -name 'log.*' ! -name '.runLock' -print0 | xargs -0 md5sum | sort > "$1"; }
gone() { local now; now=$(find . -type f ! -path './system/*' ! -path './constant/*' ! -name 'log.*' ! -name '.runLock' -print0 | xargs -0 md5sum | awk '{print $1}' | sort -u); awk '{print $1, $2}' "$1" | while read s f; do grep -q "$s" <<< "$now" || echo "$f"; done; }
#   study            a copy of tutorials/blast/pulseStudy with a one-point grid (30 MPa, 2 ns) on the small preview (20 um column, 2 ns), cd there
#   cal              a copy of tutorials/calibration/averageCell (mesh made), cd there
study() { cp -r "$ROOT/tutorials/blast/pulseStudy" "$W/study"; cd "$W/study"; sed -i 's/^baseOptions .*/baseOptions     (-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 20e-6 -endTime 2e-9);/; s/^overpressure .*/overpressure    (30e6);/; s/^duration .*/duration        (2e-9);/; s/^nProcs .*/nProcs          1;/' system/pulseStudyDict; }
cal() { cp -r "$ROOT/tutorials/calibration/averageCell" "$W/cal"; cd "$W/cal"; }
setStudy() { sed -i "s/^$1 .*/$1 $2;/" system/pulseStudyDict; }   # setStudy ENTRY VALUE
#   each FILE "ENTRY VALUE"... -- CMD...   for each edit (results of an accepted run reported, then removed): the original FILE back, ENTRY set to VALUE (sed on a line "ENTRY ...;", else appended), try CMD
each() { local f=$1; shift; local edits=(); while [ $# -gt 0 ] && [ "$1" != "--" ]; do edits+=("$1"); shift; done; shift; cp "$f" "$W/each.orig"
  for e in "${edits[@]}"; do cp "$W/each.orig" "$f"; local k=${e%% *} v=${e#* }; if grep -q "^ *$k " "$f"; then sed -i "0,/^\( *\)$k .*/s//\1$k $v;/" "$f"; else echo "$k $v;" >> "$f"; fi; try "$e" "$@"; [ -d solid ] || [ -d postProcessing ] && echo "    (the run wrote results: $(ls -d [1-9]* solid postProcessing 2>/dev/null | tr '\n' ' '); removed for the next edit)"; rm -rf solid postProcessing [1-9]*; done; cp "$W/each.orig" "$f"; }
#   inDir DIR        "pid:command line (in its directory)" of every process but this script whose working directory is under DIR
inDir() { for d in /proc/[0-9]*; do local q=${d#/proc/}; [ "$q" = $$ ] || [ "$q" = $BASHPID ] && continue; c=$(readlink $d/cwd 2>/dev/null) || continue; case "$c" in "$1"*) echo -n "$q:$(tr '\0' ' ' < $d/cmdline 2>/dev/null | cut -c1-60) (in ${c#$1}); ";; esac; done; }
#   prev             a copy of tutorials/blast/axisymmetricPreview in $W/c (cd there); PREV holds the small Allrun options (20 um column, 2 ns... set END)
prev() { cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/c; cd $W/c; }
PREV="-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 20e-6 -writeInterval 1e-9 -noPlots -noVTK"
#   killIn DIR       SIGKILL, by process id, every process (but this script) whose working directory is under DIR (all started by the case)
killIn() { for d in /proc/[0-9]*; do local q=${d#/proc/}; [ "$q" = $$ ] || [ "$q" = $BASHPID ] && continue; c=$(readlink $d/cwd 2>/dev/null) || continue; case "$c" in "$1"*) kill -KILL $q 2>/dev/null;; esac; done; }
