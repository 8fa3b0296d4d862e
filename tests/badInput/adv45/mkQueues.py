#!/usr/bin/python3
"""mkQueues.py: phase 1's queues of earlier cases. queueN.txt: every case any earlier report judged other than OK at some
time (everNonOk.py); queueS.txt: a sample of the others (random.Random(45), per pass a fifth, at least 3, every pass);
queueR.txt: the rest of the others (run if time allows)."""
import glob, os, random, subprocess
bi = os.path.dirname(os.path.dirname(os.path.abspath(__file__))); here = os.path.join(bi, 'adv45')
ever = [tuple(l.split()) for l in subprocess.run(['/usr/bin/python3', os.path.join(here, 'everNonOk.py')], capture_output=True, text=True).stdout.splitlines()]
passes = ['adv35', 'adv36', 'adv37', 'adv38', 'adv39', 'adv40', 'adv41', 'adv42', 'adv43', 'adv44']
r = random.Random(45); S, R = [], []
for p in passes:
    ok = [(p, os.path.basename(f)[:-3]) for f in sorted(glob.glob('%s/%s/cases/*.sh' % (bi, p))) if (p, os.path.basename(f)[:-3]) not in set(ever)]
    n = max(3, round(len(ok) / 5)); s = r.sample(ok, min(n, len(ok))); S += sorted(s); R += [c for c in ok if c not in s]
for name, q in (('queueN.txt', ever), ('queueS.txt', S), ('queueR.txt', R)):
    open(os.path.join(here, name), 'w').write(''.join('%s %s\n' % c for c in q))
    print(name, len(q))
