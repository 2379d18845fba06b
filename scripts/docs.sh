#!/usr/bin/env bash
# Builds the manual and the reference (HTML) with Doxygen into build/doc/html, and
# fails if Doxygen reports any warning (listed from build/doc/warnings.log) or if the
# HTML breaks one of the manual's rules:
#   - the Getting started page exists;
#   - nothing is loaded from a CDN (the formulas use the local MathJax in html/mathjax,
#     Debian's libjs-mathjax, so the manual renders offline);
#   - every examples/Range_space_remeshing/*.cpp has its page (an \example entry,
#     doc/Range_space_remeshing/examples.txt); the command-line program, in tools/,
#     is no example.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh doxygen libjs-mathjax
export RSR_DOC_OUTPUT="$PWD/build/doc"
rm -rf "$RSR_DOC_OUTPUT"
mkdir -p "$RSR_DOC_OUTPUT"
doxygen doc/Range_space_remeshing/Doxyfile
if [ -s "$RSR_DOC_OUTPUT/warnings.log" ]; then
  cat "$RSR_DOC_OUTPUT/warnings.log" >&2
  echo "docs: $(wc -l < "$RSR_DOC_OUTPUT/warnings.log") warning line(s)" >&2
  exit 1
fi
html="$RSR_DOC_OUTPUT/html"

# MathJax next to the HTML (the Doxyfile's MATHJAX_RELPATH = mathjax), without the
# package's unminified sources and tests
mathjax=/usr/share/javascript/mathjax
mkdir -p "$html/mathjax"
for part in "$mathjax"/*; do
  case "$(basename "$part")" in unpacked|test) continue ;; esac
  cp -rL "$part" "$html/mathjax/"
done

failures=()
getting_started="$html/getting_started.html"
[ -s "$getting_started" ] || failures+=("the Getting started page is missing ($getting_started)")

# a CDN anywhere in the generated pages and scripts (MathJax's own files link to
# www.mathjax.org in its About menu and licence headers, which load nothing: only
# CDN hosts count there)
cdn_hosts='cdn\.jsdelivr\.net|cdnjs\.cloudflare\.com|cdn\.mathjax\.org|unpkg\.com|ajax\.googleapis\.com|code\.jquery\.com|cdn\.[a-z0-9.-]+'
while IFS= read -r file; do
  failures+=("${file#"$html"/} loads from a CDN: $(grep -oE "https?://($cdn_hosts)[^\"' ]*" "$file" | head -1)")
done < <(grep -rlE "https?://($cdn_hosts)" "$html" || true)
while IFS= read -r file; do
  failures+=("${file#"$html"/} refers to mathjax.org: $(grep -oE 'https?://[a-z0-9.]*mathjax\.org[^"'"'"' ]*' "$file" | head -1)")
done < <(grep -rlE 'https?://[a-z0-9.]*mathjax\.org' --include='*.html' "$html" || true)
grep -qF 'src="mathjax/MathJax.js' "$html/index.html" \
  || failures+=("index.html does not load the local MathJax (mathjax/MathJax.js)")

# every example program has its page in the manual
for example in examples/Range_space_remeshing/*.cpp; do
  name="$(basename "$example")"
  grep -lF "Range_space_remeshing/$name" "$html"/*-example.html > /dev/null 2>&1 \
    || failures+=("$example has no page in the manual (add '\\example Range_space_remeshing/$name' to doc/Range_space_remeshing/examples.txt)")
done

if [ ${#failures[@]} -gt 0 ]; then
  printf 'docs: %s\n' "${failures[@]}" >&2
  exit 1
fi
echo "docs: $html/index.html"
