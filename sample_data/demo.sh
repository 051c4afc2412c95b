#!/bin/sh
# The README's demo: the bundled sample city as it stood in 1750 and in 1990, sun in the
# south-east at 30°. Usage: sh sample_data/demo.sh [OUTDIR] (default demo), from the
# repository root.
set -e
out=${1:-demo}
here=$(dirname "$0")
cityshade build "$here/sample_city.gml" -o "$out/city.cityshade"
for year in 1750 1990; do
  cityshade render "$out/city.cityshade" --city-date $year --sun-azimuth 135 --sun-elevation 30 \
    -o "$out/city_$year.exr" --png "$out/city_$year.png"
  cityshade render "$out/city.cityshade" --city-date $year --sun-azimuth 135 --sun-elevation 30 \
    --camera map --pixel-size 0.5 -o "$out/map_$year.exr" --mask "$out/map_${year}_mask.png" \
    --geotiff "$out/map_${year}_mask.tif" --decorate
done
echo "demo: pictures in $out/ (city_1750.png, city_1990.png, map_1750_mask.png, map_1990_mask.png)"
