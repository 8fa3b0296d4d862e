#!/bin/bash
# CASETIMEOUT=900
# k10 (adv49b i30 / fix19f's allrunNotALink and the run lock through a BIND path: one case seen at two paths that
# realpath cannot unify; unprivileged user+mount namespaces (`unshare -rm`, as a rootless container does) stand in for a
# bind mount by root): the finished preview bd ($C, its Allclean copied in) bound at $W/bind inside the namespace:
# (a) `$W/bind/Allclean` in the namespace (cleans the case: it is the case), (b) cellBlastFoam restarted to 3e-9 running
# in $C (outside) and, 3 s later, `cellBlastFoam` started in $W/bind inside the namespace: refused naming the running
# solver (never two runs in one case), (c) the same with `$W/bind/Allclean` inside the namespace while the solver runs
# (refused, nothing removed), (d) the reverse: the solver in the namespace at $W/bind, `$C/Allclean` outside 3 s later.
# Each: one run per case, no user or run file lost; the outcome named.
. "$(dirname "$0")/../lib.sh"
# ns CMD: CMD run by bash in a user+mount namespace where $C is bound at $W/bind, from $W/bind (a script, not a function:
# tryt's timeout runs programs; the first run of this case called a function through timeout: rc 127, n/r)
ns() { printf '%s\n' "mount --bind '$C' '$W/bind' || { echo 'bind failed'; exit 9; }" "cd '$W/bind' || exit 9" "$1" > $W/ns.sh; unshare -rm bash $W/ns.sh; }
nsx() { printf '%s\n' "mount --bind '$C' '$W/bind' || { echo 'bind failed'; exit 9; }" "cd '$W/bind' || exit 9" "$1" > $W/ns.sh; tryt $2 "$3" unshare -rm bash $W/ns.sh; }
fresh() { cd $W; rm -rf blast bind; mkdir -p bind; bd; cp "$ROOT/tutorials/blast/axisymmetricPreview/Allclean" .; C=$PWD; }
state() { echo "   case: $(cd $C; ls -d [0-9]* solid constant/cell.msh 2>/dev/null | tr '\n' ' ')| markers: $(cd $C; ls [0-9]*/.writeCommitted 2>/dev/null | wc -l) | lock: $(head -c 200 $C/.runLock 2>/dev/null | tr '\n' ' ')"; }
fresh; nsx ./Allclean 60 "(a) \$W/bind/Allclean in the namespace"; state
fresh; rs; rm -f .runLock; (cellBlastFoam > log.bg 2>&1; echo "bg rc $?" >> log.bg) & bp=$!; sleep 3; echo "   lock before: $(head -c 200 $C/.runLock 2>/dev/null | tr '\n' ' ')"
nsx "cellBlastFoam > log.ns 2>&1; echo ns rc \$?; tail -5 log.ns" 120 "(b) cellBlastFoam in \$W/bind (namespace) while one runs in \$C"; echo "   ns: $(grep -a -m3 'rc\|lock\|use\|stale\|Removing' $W/try.log | cut -c1-300 | tr '\n' '|')"; wait $bp; echo "   outside solver: $(tail -1 $C/log.bg)"; state
fresh; rs; rm -f .runLock; (cellBlastFoam > log.bg 2>&1; echo "bg rc $?" >> log.bg) & bp=$!; sleep 3
nsx ./Allclean 60 "(c) \$W/bind/Allclean (namespace) while cellBlastFoam runs in \$C"; echo "   ns: $(grep -a -m3 'lock\|use\|stale\|Removing\|error' $W/try.log | cut -c1-300 | tr '\n' '|')"; wait $bp; echo "   outside solver: $(tail -1 $C/log.bg)"; state
fresh; rs; rm -f .runLock; (ns "cellBlastFoam > log.ns 2>&1; echo ns rc \$? >> log.ns" > $W/ns.out 2>&1 &) ; sleep 4; echo "   ns start: $(cat $W/ns.out)"; echo "   lock: $(head -c 200 $C/.runLock 2>/dev/null | tr '\n' ' ')"
tryt 60 "(d) \$C/Allclean outside while cellBlastFoam runs in the namespace at \$W/bind" $C/Allclean; sleep 1; for i in $(seq 60); do pgrep -f "unshare -rm bash $W/ns.sh" > /dev/null || break; sleep 2; done; echo "   ns solver: $(tail -1 $C/log.ns 2>/dev/null)"; state
