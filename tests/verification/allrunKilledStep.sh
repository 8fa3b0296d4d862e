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
#  - with only log.APP.running removed, still refused (adv38 x45: no End
#    line, no exit status);
#  - the refusal's advice followed word for word (adv40 z31): its command
#    line, run as printed, runs the solver with its log kept, and the next
#    ./Allrun finishes, taking the step as run;
#  - after ./Allclean, ./Allrun (the real solver) runs to its end and
#    leaves no marker, the steps' exit status recorded;
#  - a runApplication step (setRiemannProblem) killed the same way is run
#    again by the next ./Allrun, saying why (adv38 x42-x44);
#  - the Allrun's shell alone killed, its solver going on: the next
#    ./Allrun names it running; once it ended with End, it is taken as
#    run (adv38 x02).
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
# Only the mark removed (the "(rm ... first)" of the advice read alone,
# adv38 x45: the solver was then skipped as run, exit 0): its log has no
# End line and no exit status was recorded, still refused
rm -f "log.$app.running"
status=0
./Allrun > log.allrun2b 2>&1 || status=$?
check "with only its mark removed, the same ./Allrun still refuses the step" \
    "[ $status -ne 0 ] && grep -q \"$app was stopped before its end .*has no End line and no exit status was recorded\" log.allrun2b"
# The advice followed word for word (adv40 z31: it named a file that did
# not exist, and the hand run it described left an Allrun that could never
# finish): its command line run as printed (the real solver, from the
# latest time), then ./Allrun finishes, the step taken as run
cmd=$(grep -A1 'To continue the solver from its last complete time instead' log.allrun2b | tail -n 1)
check "the advice gives the hand run's command" "[ -n \"$cmd\" ] && grep -q \"rm -f log.$app.running log.$app.status; $app > log.$app 2>&1\" log.allrun2b"
sed -i 's/^startFrom .*/startFrom latestTime;/' system/controlDict
status=0
bash -c "$cmd" || status=$?
check "the hand run as advised ends well" "[ $status -eq 0 ] && grep -q '^End' log.$app"
status=0
./Allrun > log.allrun2c 2>&1 || status=$?
check "and the next ./Allrun finishes, the step taken as run" \
    "[ $status -eq 0 ] && grep -q \"$app already run\" log.allrun2c"
cp "$root/tutorials/verification/sodIdealGas/system/controlDict" system/controlDict
./Allclean > /dev/null 2>&1
status=0
./Allrun > log.allrun3 2>&1 || status=$?
check "after ./Allclean, ./Allrun runs to its end" "[ $status -eq 0 ] && grep -q '^End' log.$app"
check "and leaves no marker, its steps' exit status recorded" \
    "[ ! -e log.$app.running ] && [ \"\$(cat log.$app.status)\" = 0 ] && [ \"\$(cat log.blockMesh.status)\" = 0 ]"

# A runApplication step (not runStep) killed with its Allrun (adv38 x42,
# x43, x44: blockMesh, planeWave -inflow, planeWave skipped as "already
# run" by the next ./Allrun, which then failed on a missing mesh or wave,
# or drew the figures without the reference): run again, saying why
./Allclean > /dev/null 2>&1
printf '#!/bin/bash\necho "Starting (stand-in)"\nexec sleep 60\n' > "$work/fake/setRiemannProblem"
chmod +x "$work/fake/setRiemannProblem"
PATH="$work/fake:$PATH" setsid ./Allrun > log.allrun4 2>&1 &
pid=$!
for _ in $(seq 300); do grep -qs 'Starting (stand-in)' log.setRiemannProblem && break; sleep 0.1; done
kill -KILL -- -"$pid" 2>/dev/null
wait "$pid" 2>/dev/null
sleep 0.5
status=0
./Allrun > log.allrun5 2>&1 || status=$?
check "a killed runApplication step is run again by the next ./Allrun, saying why" \
    "grep -q 'setRiemannProblem was stopped before its end .*running it again' log.allrun5 \
     && ! grep -qs 'Starting (stand-in)' log.setRiemannProblem \
     && [ \"\$(cat log.setRiemannProblem.status)\" = 0 ]"
check "and the case then runs to its end" "[ $status -eq 0 ] && grep -q '^End' log.$app"
rm -f "$work/fake/setRiemannProblem"

# The Allrun's shell killed, its solver going on (adv38 x02): while it
# runs, the next ./Allrun names it running; once it ended well (its log
# ends with End) its run is taken as done, not called partial
./Allclean > /dev/null 2>&1
printf '#!/bin/bash\necho "Starting (stand-in)"\nsleep 6\necho End\n' > "$work/fake/$app"
PATH="$work/fake:$PATH" ./Allrun > log.allrun6 2>&1 &
pid=$!
for _ in $(seq 300); do grep -qs 'Starting (stand-in)' "log.$app" && break; sleep 0.1; done
kill -KILL "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
status=0
PATH="$work/fake:$PATH" ./Allrun > log.allrun7 2>&1 || status=$?
check "the orphan solver still running: the next ./Allrun refuses, naming it running" \
    "[ $status -ne 0 ] && grep -q \"$app is still running in this case (pid\" log.allrun7"
for _ in $(seq 200); do grep -qs '^End' "log.$app" && break; sleep 0.1; done
sleep 0.5
PATH="$work/fake:$PATH" ./Allrun > log.allrun8 2>&1
check "once it ended well: taken as run (not partial, not run again)" \
    "grep -q \"$app ended after the run of this Allrun that started it was stopped\" log.allrun8 \
     && ! grep -q 'partial' log.allrun8 && [ \"\$(grep -c 'Starting (stand-in)' log.$app)\" = 1 ]"
exit $fail
