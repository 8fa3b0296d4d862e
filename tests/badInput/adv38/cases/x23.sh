#!/bin/bash
# x23: a material set #include'd twice in solidProperties (the same file, the user pasted the line twice), and the same file #include'd in two regions: a clear error or accepted (identical values), no crash? (indentation, fresh run)
. "$(dirname "$0")/../lib.sh"
ind; grep -n "#include" constant/solidProperties | head -5; inc=$(grep -m1 "#include" constant/solidProperties)
cp constant/solidProperties ../sp0; sed -i "0,/$(echo "$inc" | sed 's/[\/&"]/\\&/g')/s//&\n$(echo "$inc" | sed 's/[\/&"]/\\&/g')/" constant/solidProperties; grep -n "#include" constant/solidProperties | head -4
try "include twice" cellIndentationFoam; rm -rf postProcessing
