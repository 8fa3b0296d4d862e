# Shared by the shell tests that list checks (tests/fsi/caseLock.sh,
# tests/verification/resultGuard.sh, restartInputs.sh, overwriteUserFiles.sh,
# overwriteUserLogs.sh). Sourced, it sets fail=0 and defines:
#   check WHAT CONDITION   evaluates the shell code CONDITION, prints
#                          "ok   WHAT" or "FAIL WHAT" (then fail=1);
#                          the script ends with exit $fail
#   caseSums [PATTERN...]  md5 of every file below the current directory
#                          whose name matches none of the PATTERNs
#                          (default log.*), sorted: equal output,
#                          unchanged files
#   waitFor SECONDS CMD... until CMD succeeds (every 0.1 s); non-zero if
#                          it did not within SECONDS
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }
caseSums()
{
    local not=() p
    for p in "${@:-log.*}"
    do
        not+=(! -name "$p")
    done
    find . -type f "${not[@]}" -print0 | sort -z | xargs -0 md5sum
}
waitFor()
{
    local n=$(( $1 * 10 ))
    shift
    while [ $n -gt 0 ]
    do
        "$@" && return 0
        sleep 0.1
        n=$((n - 1))
    done
    return 1
}
