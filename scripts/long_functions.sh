#!/usr/bin/env bash
# Lists functions in the given source folders longer than a limit (default 80 lines), using
# Universal Ctags' end-line field. A function may stay longer when a comment containing
# "long-function:" sits within the three lines above its definition, giving the reason.
# Usage: scripts/long_functions.sh [--limit N] DIR...
set -euo pipefail
limit=80
if [[ "${1:-}" == "--limit" ]]; then limit="$2"; shift 2; fi
status=0
while IFS=$'\t' read -r name file line end; do
  length=$((end - line + 1))
  (( length > limit )) || continue
  from=$((line > 3 ? line - 3 : 1))
  if sed -n "${from},${line}p" "$file" | grep -q 'long-function:'; then continue; fi
  echo "$file:$line: $name is $length lines (limit $limit)"
  status=1
done < <(ctags -R --c++-kinds=f --fields=+ne --languages=C++ -o - "$@" 2>/dev/null \
         | awk -F'\t' '{ l=""; e=""; for (i=4;i<=NF;i++) { if ($i ~ /^line:/) l=substr($i,6); if ($i ~ /^end:/) e=substr($i,5) }
                          if (l != "" && e != "" && $1 !~ /^__anon/) print $1 "\t" $2 "\t" l "\t" e }')
exit $status
