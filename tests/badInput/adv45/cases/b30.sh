#!/bin/bash
# b30 (class 4+2, planeWave -inflow with constant/ read-only, and through a linked case folder): (a) constant/ a read-only bind mount, planeWave -inflow 20e-6 -Z 40e-6 -overwrite (planeWave's default -dz, not the Allrun's: another wave, it must write): an error naming the file or folder, no traceback, constant/inflowWave unchanged; (b) the case reached through a symbolic link ($W/lc -> the case), planeWave -case $W/lc -inflow 20e-6 -Z 40e-6: the same wave found (nothing written), the link kept?
. "$(dirname "$0")/../lib.sh"
iblast; md5sum constant/inflowWave > ../m; ro constant
tryf "(a) read-only constant/" planeWave $IW -overwrite; umount constant; echo "   inflowWave: $(md5sum -c ../m 2>&1 | awk '{print $2}'); left in constant/: $(ls -a constant | grep -v '^\.\.\?$' | tr '\n' ' ')"
ln -s $W/c $W/lc; tryf "(b) through a linked case" planeWave -case $W/lc $IW; echo "   link: $(readlink $W/lc); inflowWave: $(md5sum -c ../m 2>&1 | awk '{print $2}')"
