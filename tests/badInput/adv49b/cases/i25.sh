#!/bin/bash
# i25 (class 3, stale and live-looking locks of this host): bd restarted (rs) with .runLock naming this host and (a) a pid alive
# nowhere (4194000), started 2019; (b) the pid of a live `sleep` (another executable); (c) the pid of a live process whose
# name is cellBlastFoam (a copy of sleep so named), its start time (since P1b: in P1 the lock's start time was not the
# process's, a reused pid, rightly taken over) and this case: a live run, refused; (d) as (c) but the lock naming another
# case folder (a copied lock): refused or taken over, saying it names another case; (e) started in the future (2099), pid gone;
# (f) pid 0, (g) pid -1, (h) pid 4294967297, (i) pid "12x". (a) (b) (e) taken over as stale, saying so, and the restart runs
# (exit 0); (c) refused naming the process; (f)-(i) refused as damaged (never taken as a live pid 1 or the process group).
. "$(dirname "$0")/../lib.sh"
bd; rs; H=$(hostname); mkdir -p $W/bin; cp /bin/sleep $W/bin/cellBlastFoam; sleep 300 & S=$!; $W/bin/cellBlastFoam 300 & C=$!; sleep 0.2; CS=$(date -d "$(ps -o lstart= -p $C)" +%Y-%m-%dT%H:%M:%S); echo "   fake cellBlastFoam $C started $CS"
lockw() { printf 'pid %s\nhost %s\nexecutable cellBlastFoam\nstarted %s\ncase %s\n' "$1" "$H" "${3:-2026-12-06T00:00:00}" "${2:-$PWD}" > .runLock; }
t() { cp -a $W/blast $W/t; cd $W/t; sed -i "s|^case .*|case ${2:-$PWD}|" .runLock; tryt 120 "$1" cellBlastFoam; echo "   said: $(grep -a -m2 -i 'stale\|taken\|lock\|in use' $W/try.log | cut -c1-220 | tr '\n' '|')"; echo "   lock now: $(lockOf)"; after; cd $W; rm -rf $W/t; }
cd $W/blast; lockw 4194000 "" 2019-01-01T00:00:00; t "(a) pid gone"
cd $W/blast; lockw $S; t "(b) a live sleep"
cd $W/blast; lockw $C "" $CS; t "(c) a live 'cellBlastFoam' of this case"
cd $W/blast; lockw $C /tmp/elsewhere/case $CS; t "(d) a live 'cellBlastFoam' of another case" /tmp/elsewhere/case
cd $W/blast; lockw 4194000 "" 2099-01-01T00:00:00; t "(e) started in 2099, pid gone"
for p in 0 -1 4294967297 12x; do cd $W/blast; lockw $p; t "(f-i) pid $p"; done
kill $S $C
