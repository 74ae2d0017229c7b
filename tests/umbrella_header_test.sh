#!/usr/bin/env bash
# include/raster/raster.hpp includes every public header under include/raster/, and nothing
# that is not there (version.hpp is generated into the build).
set -euo pipefail
cd "$1/include"
umbrella=raster/raster.hpp
listed=$(sed -n 's/^#include <\(raster\/[^>]*\)>.*/\1/p' "$umbrella" | sort)
status=0
for header in $(find raster -name '*.hpp' ! -path "$umbrella" | sort); do
    grep -qxF -- "$header" <<<"$listed" || { echo "$umbrella does not include <$header>"; status=1; }
done
for header in $listed; do
    [ -f "$header" ] || [ "$header" = raster/version.hpp ] || { echo "$umbrella includes <$header>, which is not there"; status=1; }
done
exit $status
