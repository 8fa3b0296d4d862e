# lib.sh (adv46b): adv45's lib.sh (tests/badInput/adv45: all helpers of adv35-adv45: ind/indDone, indKilled, blast/blastDone,
# pblast/pblastDone, iblast/iEnd/IW, blastEnd, latest, restart0, sums, changed, nochange, kept, where, tryf, try, run, fatal,
# waitFor, sameSeries, study, setStudy, cal, prev/PREV, flip, h5same, h5steps, xmfsteps, nul, marks, lockOf, ro, tiny, ODD ...)
# with ADV defaulting to /tmp/adv46b-adv46b
ADV=${ADV:-/tmp/adv46b-adv46b}
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv45/lib.sh"
# plus (adv46b), bases built once by prebuild.sh (copied with cp -a into $W, so that cases running two at a time build nothing):
#   bd     a finished blast preview (blastDone: times 1e-09, 2e-09), cd there; rs: then startFrom latestTime, endTime 3e-9,
#          writeInterval 1e-9 (the plain restart of the finished run)
#   idn    a finished smoke indentation (indDone), cd there
#   ik     a smoke indentation with 10x finer depth steps SIGKILLed 1 s after its first checkpoint (indKilled 1; its stale
#          .runLock removed), startFrom latestTime, cd there
#   tryt N LABEL CMD...   tryf with a KILL timeout of N s (rc 137: killed by it)
#   after  what the case holds now: time directories, solid.h5 steps, force.dat rows
mkBase_() { [ -d "$ADV/$1" ] && return 0; ( W=$ADV/.mk$1; rm -rf $W; mkdir -p $W; $2 > $ADV/$1.log 2>&1; rm -f $W/$3/.runLock; mv $W/$3 $ADV/$1 && rm -rf $W ); }
bd() { mkBase_ bdBase blastDone blast; cp -a $ADV/bdBase $W/blast; cd $W/blast; }
rs() { latest; blastEnd 3e-9 1e-9; }
idn() { mkBase_ idBase indDone ind; cp -a $ADV/idBase $W/ind; cd $W/ind; }
ik() { mkBase_ ikBase "indKilled 1" ind; cp -a $ADV/ikBase $W/ind; cd $W/ind; }
tryt() { local n=$1 l=$2; shift 2; timeout -s KILL $n "$@" > $W/try.log 2>&1; local rc=$?; echo "$l: rc=$rc | $(grep -a -m1 -A3 'FATAL\|error:\|Error\|Traceback\|refused\|[Rr]efus' $W/try.log | grep -av '^ *$\|^-->\|From function\|^\[.\] *$' | head -3 | tr '\n' ' ' | cut -c1-420)"; }
after() { echo "   now: times $(ls -d [0-9]* 2>/dev/null | tr '\n' ' ')| aside $(ls -d .*overwritten* *.interrupted* 2>/dev/null | tr '\n' ' ')| solid.h5 $([ -f solid/solid.h5 ] && h5steps solid/solid.h5 || ([ -f postProcessing/indentation/solid.h5 ] && h5steps postProcessing/indentation/solid.h5) || echo none) steps | force.dat $(grep -vc '^#' postProcessing/indentation/force.dat 2>/dev/null) rows"; }
cont() { grep -a -m2 -i 'continu\|restart\|resum' $W/try.log | cut -c1-200 | sed 's/^/   log: /'; }
