#!/usr/bin/python3
"""mkQueues.py: adv46a's phase-1 queues, in the brief's order. queueB.txt: adv45's b01-b48 and c01-c05 (every one);
queueN.txt: every case any earlier report (adv35-adv45) judged other than OK at some time (everNonOk.py), without adv45's
(in queueB), adv38-adv44 first (adv45's phase 1 reached only adv35-adv37's), then adv35-adv37; queueA44.txt: adv44's
a01-a43 not in queueN; queueS.txt: adv35's other cases (its originals), in a random order (random.Random(46))."""
import glob, os, random, subprocess
bi = os.path.dirname(os.path.dirname(os.path.abspath(__file__))); here = os.path.join(bi, 'adv46a')
ids = lambda p: sorted(os.path.basename(f)[:-3] for f in glob.glob('%s/%s/cases/*.sh' % (bi, p)))
ever = [tuple(l.split()) for l in subprocess.run(['/usr/bin/python3', os.path.join(here, 'everNonOk.py')], capture_output=True, text=True).stdout.splitlines()]
B = [('adv45', i) for i in ids('adv45')]
N = [c for c in ever if c[0] != 'adv45']
N = [c for c in N if c[0] >= 'adv38'] + [c for c in N if c[0] < 'adv38']
A44 = [('adv44', i) for i in ids('adv44') if i.startswith('a') and ('adv44', i) not in set(ever)]
S = [('adv35', i) for i in ids('adv35') if ('adv35', i) not in set(ever)]; random.Random(46).shuffle(S)
for name, q in (('queueB.txt', B), ('queueN.txt', N), ('queueA44.txt', A44), ('queueS.txt', S)):
    open(os.path.join(here, name), 'w').write(''.join('%s %s\n' % c for c in q))
    print(name, len(q))
