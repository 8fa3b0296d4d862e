#!/bin/bash
# e01 (class 5, adv39 y16's third variant with the damage in a file the restart READS; written by adv46a at 16:40 after
# reading y16's output: its marker cut to 20 bytes was accepted while the cut after the T line was moved aside, and the
# restart reads rho, rhoU, rhoE, not the damaged p): a blast finished to 2 ns, 2e-09/.writeCommitted cut to its first
# 20 bytes ("2e-09\ndigest fnv1a64": the marker's tail did not reach the disk) and 64 bytes of 2e-09/rho zeroed; restart
# from latestTime to 3 ns: the time moved aside as incomplete (continues from 1e-09) or refused naming it; never a crash
# nor a run from the damaged rho? (control: the marker cut after its T line, the same damage to rho)
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cp -r . ../keep
dmg() { /usr/bin/python3 - <<'P'
s=bytearray(open('2e-09/rho','rb').read()); k=s.find(b'internalField'); k=s.find(b'(', k)+200; s[k:k+64]=b'\0'*64; open('2e-09/rho','wb').write(s)
P
}
head -3 2e-09/.writeCommitted > m; mv m 2e-09/.writeCommitted; dmg; try "control: marker cut after its T line, rho damaged" cellBlastFoam; ls -da [1-9]* 2>/dev/null | tr '\n' ' '; echo
rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast; head -c 20 2e-09/.writeCommitted > m; echo "   marker now: $(tr '\n' '|' < m)"; mv m 2e-09/.writeCommitted; dmg; try "marker cut to 20 bytes, rho damaged" cellBlastFoam; grep -a -m2 "Restarting\|sigFpe\|Floating" $W/try.log | cut -c1-160; ls -da [1-9]* 2>/dev/null | tr '\n' ' '; echo
