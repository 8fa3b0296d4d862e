# lib.sh (adv39): adv38's lib.sh (and through it adv35-37's helpers and base cases) with ADV defaulting to /tmp/adv39a
ADV=${ADV:-/tmp/adv39a}
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv38/lib.sh"
# killedAllrun S: a copy of the preview tutorial, its Allrun ($PREV -endTime 8e-9) started in its own group and the whole group SIGKILLed once time S exists
killedAllrun() { prev; setsid ./Allrun $PREV -endTime 8e-9 > ../log.a1 2>&1 & local p=$!; waitFor 120 test -d $1; kill -KILL -- -$p; wait $p 2>/dev/null; sleep 0.5; echo "killed at $1: marks $(ls log.*.running log.*.status 2>/dev/null | tr '\n' ' ')"; }
again() { run 200 ./Allrun $PREV -endTime 8e-9 > ../log.$1 2>&1; echo "Allrun ($1): $(grep -a -i "already\|error\|refus\|stopped\|again\|running" ../log.$1 | head -3 | cut -c1-220 | tr '\n' '|')"; echo "times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"; }
