#!/usr/bin/env bash
# Lists functions in the given source folders longer than a limit (default 80 lines), using
# Universal Ctags' end-line field (Debian package universal-ctags). A function may stay longer
# when a comment containing "long-function:" sits within the three lines above its definition,
# giving the reason. Exit status: 0 none, 1 some listed, 2 the check could not run (no ctags, no
# function found: a check that sees nothing must not pass).
# Usage: scripts/long_functions.sh [--limit N] DIR...
set -euo pipefail
limit=80
if [[ "${1:-}" == "--limit" ]]; then limit="$2"; shift 2; fi
if ! command -v ctags-universal >/dev/null; then
  echo "long_functions: ctags-universal not found (apt install universal-ctags)" >&2
  exit 2
fi
tags="$(ctags-universal -R --c++-kinds=f --fields=+ne --languages=C++ -o - "$@")"
status=0
seen=0
while IFS=$'\t' read -r name file line end; do
  seen=$((seen + 1))
  length=$((end - line + 1))
  (( length > limit )) || continue
  from=$((line > 3 ? line - 3 : 1))
  if sed -n "${from},${line}p" "$file" | grep -q 'long-function:'; then continue; fi
  echo "$file:$line: $name is $length lines (limit $limit)"
  status=1
done < <(awk -F'\t' '{ l=""; e=""; for (i=4;i<=NF;i++) { if ($i ~ /^line:/) l=substr($i,6); if ($i ~ /^end:/) e=substr($i,5) }
                        if (l != "" && e != "" && $1 !~ /^__anon/) print $1 "\t" $2 "\t" l "\t" e }' <<<"$tags")
if (( seen == 0 )); then
  echo "long_functions: no function found in $*" >&2
  exit 2
fi
exit $status
