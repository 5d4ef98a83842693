#!/usr/bin/env bash
# Include layering of the flight code, checked mechanically: every project include is spelled
# "visors/<layer>/..." (the installed include root), and each flight layer under src/visors/ may
# include only itself and the layers it links (its PUBLIC dependencies in
# src/visors/*/CMakeLists.txt and theirs, repeated in the table below), never a ground layer (sim,
# mc, report, config, baseline, apps) nor a ground sub-folder (*/files/: file readers and the data
# search path). Run by CTest
# (FlightCode.IncludesOnlyItsOwnLayers); prints each offending line and exits 1.
# Usage: scripts/check_layers.sh [SOURCE_DIR (the repository)]
set -euo pipefail
root=${1:-"$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"}
declare -A allowed=(
  [core]="core"
  [astro]="astro core"
  [optim]="optim core"
  [gnss]="gnss core"
  [dynamics]="dynamics astro core"
  [nav]="nav dynamics gnss astro core"
  [control]="control optim astro core"
  [safety]="safety control optim astro core"
  [gnc]="gnc nav dynamics gnss safety control optim astro core"
)
status=0
files=0
for layer in "${!allowed[@]}"; do
  while IFS= read -r file; do
    files=$((files + 1))
    while IFS= read -r line; do
      target=${line#*#include \"}
      target=${target%%\"*}
      [[ $target == */* ]] || continue            # a same-folder include
      if [[ $target != visors/* ]]; then
        echo "${file#"$root"/}: include \"$target\" is not under visors/ (the installed include root)" >&2
        status=1
        continue
      fi
      target=${target#visors/}
      top=${target%%/*}
      rest=${target#*/}
      ok=0
      for a in ${allowed[$layer]}; do [[ $top == "$a" ]] && ok=1; done
      [[ $rest == files/* ]] && ok=0
      if [[ $ok -eq 0 ]]; then
        echo "${file#"$root"/}: flight layer '$layer' includes \"$target\" (allowed: ${allowed[$layer]}; never */files/)" >&2
        status=1
      fi
    done < <(grep -E '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$file" || true)
  done < <(find "$root/src/visors/$layer" -path "$root/src/visors/$layer/files" -prune -o -type f \( -name '*.hpp' -o -name '*.cpp' -o -name '*.hpp.in' \) -print)
done
[[ $status -eq 0 ]] && echo "flight layers: ${files} files, every include within its layer's dependencies"
exit $status
