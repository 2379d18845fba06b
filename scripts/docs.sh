#!/usr/bin/env bash
# Builds the manual and the reference (HTML) with Doxygen into build/doc/html, and
# fails if Doxygen reports any warning (listed from build/doc/warnings.log).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh doxygen
export RSR_DOC_OUTPUT="$PWD/build/doc"
rm -rf "$RSR_DOC_OUTPUT"
mkdir -p "$RSR_DOC_OUTPUT"
doxygen doc/Range_space_remeshing/Doxyfile
if [ -s "$RSR_DOC_OUTPUT/warnings.log" ]; then
  cat "$RSR_DOC_OUTPUT/warnings.log" >&2
  echo "docs: $(wc -l < "$RSR_DOC_OUTPUT/warnings.log") warning line(s)" >&2
  exit 1
fi
echo "docs: $RSR_DOC_OUTPUT/html/index.html"
