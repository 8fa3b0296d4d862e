#!/bin/bash
# CASETIMEOUT=1200
# k05b: k05's walks (a) and (b) only (k05's first run in out/K missed the lower bound's "at least N elements" figure, so
# its walks stopped at maxElements 1; fixed in k05.sh at 05:20, (c)-(e) of that run stand)
K05WALKONLY=1 . "$(dirname "$0")/k05.sh"
