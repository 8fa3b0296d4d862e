#!/usr/bin/python3
"""mkTable.py DIR...: adv48a's mkTable.py run on this pass's folder (this
folder's verdicts.txt and out/DIR; the same table, arguments and -t)."""
import os
p = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                 'adv48a', 'mkTable.py')
exec(compile(open(p).read(), p, 'exec'),
     {'__file__': os.path.abspath(__file__), '__name__': '__main__'})
