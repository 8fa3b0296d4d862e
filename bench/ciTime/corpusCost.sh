#!/bin/bash
#------------------------------------------------------------------------------
# bench/ciTime/corpusCost.sh OLD NEW OUT: the bad-input corpus' CPU, two
# checkouts side by side (each built: its etc/bashrc, build/ and platforms/).
# OLD runs tests/badInput/runCorpus.sh in one go (the test badInput.corpus
# before the split); NEW runs it as ctest does since: --prepare, then the
# three shards --shard K/3 one after the other. Both at the same time,
# nice -n 10; prints the wall and CPU (user + system, /usr/bin/time) of
# each part, the load, and whether the rows' results agree (names of the
# ok and FAIL lines). Logs in OUT.
#------------------------------------------------------------------------------
set -uo pipefail
[ $# -eq 3 ] || { echo "usage: $0 OLD NEW OUT" >&2; exit 1; }
old=$(cd "$1" && pwd) new=$(cd "$2" && pwd) out=$3
# OUT new, empty or an earlier output of this script, locked for the run
# (adv53 u06: `rm -rf "$out/bases"` removed a user's OUT/bases/notes.txt)
. "$(cd "$(dirname "$0")/../.." && pwd)/etc/scratchFolder"
scratchFolder corpusCost.sh "$out" times old.log "new.*.log" bases
timed() { # label log command...: the command under /usr/bin/time
    local label=$1 log=$2; shift 2
    /usr/bin/time -f "$label %e %U %S" -a -o "$out/times" nice -n 10 "$@" \
        > "$log" 2>&1
}
echo "corpusCost: start $(date -u +%H:%M:%S) UTC, load $(cut -d' ' -f1-3 /proc/loadavg)"
( . "$old/etc/bashrc"
  export MAKE_SOLID_RESULTS=$old/build/bin/makeSolidResults
  timed old.oneGo "$out/old.log" bash "$old/tests/badInput/runCorpus.sh" ) &
( . "$new/etc/bashrc"
  export MAKE_SOLID_RESULTS=$new/build/bin/makeSolidResults
  timed new.prepare "$out/new.prepare.log" \
      bash "$new/tests/badInput/runCorpus.sh" --prepare "$out/bases"
  for k in 1 2 3
  do
      timed new.shard$k "$out/new.shard$k.log" \
          bash "$new/tests/badInput/runCorpus.sh" --bases "$out/bases" --shard $k/3
  done
  rm -rf "$out/bases" ) &
wait
echo "corpusCost: end $(date -u +%H:%M:%S) UTC, load $(cut -d' ' -f1-3 /proc/loadavg)"
awk '{ printf "  %-12s wall %7.1f s  CPU %7.1f s\n", $1, $2, $3 + $4
       if ($1 ~ /^new/) { w += $2; c += $3 + $4 } }
     END { printf "  %-12s wall %7.1f s  CPU %7.1f s\n", "new (sum)", w, c }' "$out/times"
for s in old new
do
    cat "$out/$s".*log "$out/$s.log" 2>/dev/null | grep -E '^(ok|FAIL) ' \
        | awk '{ print $1, $2 }' | sort > "$out/$s.results"
    echo "  $s: $(grep -c '^ok' "$out/$s.results") ok, $(grep -c '^FAIL' "$out/$s.results") FAIL"
done
if cmp -s "$out/old.results" "$out/new.results"
then
    echo "  the same rows ok and failed in both"
else
    echo "  the rows' results differ:"; diff "$out/old.results" "$out/new.results" | head -20
fi
