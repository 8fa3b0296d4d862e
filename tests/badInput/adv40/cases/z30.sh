#!/bin/bash
# z30: indentation finished; the user had moved force.dat and peaks.dat to an archive folder OUTSIDE the case and left symbolic links in their place; cellIndentationFoam -overwrite (a new run): is the archive outside the case written through the links (its files changed) or kept?
. "$(dirname "$0")/../lib.sh"
indDone; mkdir -p $W/archive; P=postProcessing/indentation
for f in force.dat peaks.dat; do mv $P/$f $W/archive/$f; ln -s $W/archive/$f $P/$f; done; md5sum $W/archive/* > ../before
try "-overwrite" cellIndentationFoam -overwrite
md5sum -c ../before 2>&1 | sed 's/^/   archive: /'; ls -l $P | grep -- '->' | cut -c40- | sed 's/^/   link: /'
