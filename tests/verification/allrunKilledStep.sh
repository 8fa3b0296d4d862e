#!/bin/bash
# A step of an Allrun killed with its Allrun (SIGKILL: nothing can be
# caught) is not taken for a finished step by the next ./Allrun (adv37
# w113: the blast solver killed at 2 ns, the same ./Allrun skipped it
# because its log existed, exit 0 over partial results; w114 cellMesh).
# tutorials/verification/sodIdealGas, its solver stood in by a program that
# starts and waits (the moment of the kill then certain), the Allrun and
# its children SIGKILLed as a process group while the solver runs:
#  - the same ./Allrun exits non-zero, names the step, says it was stopped
#    before its end and how to start anew, runs nothing (no file outside
#    0/ changed: the Allrun's restore0Dir, before the step, rewrites 0/
#    from 0.orig as any re-run of it does);
#  - after ./Allclean, ./Allrun (the real solver) runs to its end and
#    leaves no marker.
set -uo pipefail
. "$(dirname "$0")/../lib/checks.sh"
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
cp -r "$root/tutorials/verification/sodIdealGas" "$work/case"
cd "$work/case" && ./Allclean > /dev/null 2>&1
app=$(foamDictionary -entry application -value system/controlDict)
mkdir -p "$work/fake"
printf '#!/bin/bash\necho "Starting (stand-in)"\nexec sleep 60\n' > "$work/fake/$app"
chmod +x "$work/fake/$app"
PATH="$work/fake:$PATH" setsid ./Allrun > log.allrun1 2>&1 &
pid=$!
for _ in $(seq 300); do grep -qs 'Starting (stand-in)' "log.$app" && break; sleep 0.1; done
check "the stand-in solver started under ./Allrun" "grep -qs 'Starting (stand-in)' log.$app"
kill -KILL -- -"$pid" 2>/dev/null
wait "$pid" 2>/dev/null
sleep 0.5
results() { caseSums 'log.allrun*' | grep -v ' \./0/\| \./\.runLock$'; }  # the killed run's stale lock is removed
results > "$work/before"
status=0
./Allrun > log.allrun2 2>&1 || status=$?
check "the same ./Allrun after the kill exits non-zero" "[ $status -ne 0 ]"
check "it names the step and says it was stopped before its end" \
    "grep -q \"$app was stopped before its end\" log.allrun2"
check "it says how to start anew" "grep -q 'Allclean, then ./Allrun' log.allrun2"
results > "$work/after"
check "no file outside 0/ changed" "cmp -s '$work/before' '$work/after'"
./Allclean > /dev/null 2>&1
status=0
./Allrun > log.allrun3 2>&1 || status=$?
check "after ./Allclean, ./Allrun runs to its end" "[ $status -eq 0 ] && grep -q '^End' log.$app"
check "and leaves no marker" "[ ! -e log.$app.running ]"
exit $fail
