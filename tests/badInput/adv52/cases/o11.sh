#!/bin/bash
# CASETIMEOUT=600
# o11 (fix19h's plot scripts on missing results, adv51 n05, varied: the other plot scripts and damaged inputs):
# (a) tutorials/indentation/plotFields.py on a folder that does not exist, and on a case without solid.h5;
# (b) plotFields.py on the finished indentation with 64 zeroed bytes in postProcessing/indentation/solid.h5's last step;
# (c) tutorials/blast/plotBlast.py on the finished preview with solid/solid.h5 cut to half its size;
# (d) tutorials/verification/plotShockTube.py without an argument and on a folder that is no case;
# (e) tutorials/indentation/plotIndentation.py on a case whose force.dat is a folder. Each: its usage or one line naming
# the file, rc != 0; never a traceback; never a figure drawn from damaged data without a word.
. "$(dirname "$0")/../lib.sh"
T=$ROOT/tutorials
py() { local l=$1; shift; tryt 120 "$l" /usr/bin/python3 "$@"; echo "   traceback: $(grep -a -c Traceback $W/try.log) | out: $(grep -a -v '^ *$' $W/try.log | tail -2 | tr '\n' '|' | cut -c1-300) | new png: $(find . -newer $W/t0 -name '*.png' 2>/dev/null | tr '\n' ' ')"; }
touch $W/t0; cd $W
py "(a1) plotFields.py on a folder that does not exist" $T/indentation/plotFields.py $W/nothere
idn; touch $W/t0; mv postProcessing/indentation/solid.h5 $W/solid.h5.keep
py "(a2) plotFields.py on a case without solid.h5" $T/indentation/plotFields.py .
cp $W/solid.h5.keep postProcessing/indentation/solid.h5; /usr/bin/python3 - postProcessing/indentation/solid.h5 <<'P'
import h5py, sys
f = h5py.File(sys.argv[1], 'r'); ks = sorted(f['steps'].keys(), key=lambda k: int(k)); d = f['steps'][ks[-1]]
ds = [d[n] for n in d.keys() if isinstance(d[n], h5py.Dataset)][0]; off = ds.id.get_offset()
off = ds.id.get_chunk_info(0).byte_offset if off is None else off; f.close()
with open(sys.argv[1], 'r+b') as g: g.seek(off + 16); g.write(b'\0' * 64)
print('   zeroed 64 bytes in step', ks[-1])
P
touch $W/t0; py "(b) plotFields.py on solid.h5 with 64 zeroed bytes in its last step" $T/indentation/plotFields.py .
mkdir -p pp; mv postProcessing/indentation/force.dat pp/; mkdir postProcessing/indentation/force.dat; touch $W/t0
py "(e) plotIndentation.py with force.dat a folder" $T/indentation/plotIndentation.py .
cd $W; bd; touch $W/t0; s=$(stat -c %s solid/solid.h5); truncate -s $((s/2)) solid/solid.h5
py "(c) plotBlast.py on solid.h5 cut to half" $T/blast/plotBlast.py .
touch $W/t0; py "(d1) plotShockTube.py without an argument" $T/verification/plotShockTube.py
mkdir -p $W/nocase; cd $W/nocase; touch $W/t0; py "(d2) plotShockTube.py on a folder that is no case" $T/verification/plotShockTube.py $W/nocase
