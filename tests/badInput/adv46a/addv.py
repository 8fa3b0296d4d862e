#!/usr/bin/python3
"""addv.py PASS_ID VERDICT NOTE: adds (or replaces) my verdict of one output in verdicts.py"""
import sys, os, re
f = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'verdicts.py')
k, v, n = sys.argv[1:4]; t = open(f).read()
t = re.sub(r'^ %r: .*\n' % k if False else r'(?m)^ "%s": .*\n' % re.escape(k), '', t)
t = t.rstrip().rstrip('}') + ' "%s": (%r, %r),\n}\n' % (k, v, n)
open(f, 'w').write(t)
