# Shared by the restart tests: tests/verification/restartKilledWrites.sh,
# tests/indentation/restartIndentation.sh, tests/blast/restart.sh,
# tests/blast/restartKilledWrites.sh, tests/blast/parallel.sh. Sourced
# (after set -euo pipefail), it sets the project environment (etc/bashrc),
# $root (the project) and $work (a temporary directory removed at exit,
# kept with KEEP_WORK=1), and defines runUntil and sameFiles.
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
[ -n "${KEEP_WORK:-}" ] || trap 'rm -rf "$work"' EXIT

# runUntil SIGNAL CONDITION LOG COMMAND...
#   Runs COMMAND in the background (stdout and stderr to LOG), evaluates
#   the shell code CONDITION every runUntilPoll seconds (default 0.01; 0:
#   without pause, to catch a state that lasts milliseconds, with a
#   CONDITION of shell built-ins only) while it runs and sends SIGNAL
#   (KILL, TERM, ...) as soon as CONDITION holds; waits for the process.
#   Fails (status 1, the end of LOG printed) if COMMAND ends first.
runUntil()
{
    local signal=$1 condition=$2 log=$3 poll=${runUntilPoll:-0.01}
    shift 3
    "$@" > "$log" 2>&1 &
    local pid=$!
    until eval "$condition"
    do
        if ! kill -0 $pid 2> /dev/null
        then
            wait $pid 2> /dev/null || true
            echo "runUntil: $1 ended before [$condition] held; $log:" >&2
            tail -5 "$log" >&2
            return 1
        fi
        [ "$poll" = 0 ] || sleep "$poll"
    done
    if ! kill -s "$signal" $pid 2> /dev/null
    then
        echo "runUntil: $1 ended before SIG$signal" >&2
        return 1
    fi
    wait $pid 2> /dev/null || true
}

# sameFiles DIR_A DIR_B FILE...
#   True if every FILE (a path relative to both directories) is byte-equal
#   in DIR_A and DIR_B; names the files that differ or are missing.
sameFiles()
{
    local a=$1 b=$2 f status=0
    shift 2
    for f in "$@"
    do
        if ! cmp -s "$a/$f" "$b/$f"
        then
            echo "sameFiles: $f differs between $a and $b (or is missing)"
            status=1
        fi
    done
    return $status
}
