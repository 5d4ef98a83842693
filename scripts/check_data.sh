#!/usr/bin/env bash
# Checks the reference data shipped in data/: every file listed in data/SHA256SUMS is there with
# its checksum, and every data file (outside scenarios/ and campaigns/, the project's own) is
# listed, so that none ships without its provenance in data/SOURCES.md. Run by CTest (DataFiles.ChecksumsAndProvenanceComplete).
# Usage: scripts/check_data.sh [DATA_DIR (data/ beside this script)]
set -euo pipefail
data=${1:-"$(cd "$(dirname "${BASH_SOURCE[0]}")/../data" && pwd)"}
cd "$data"
sha256sum --check --strict --quiet SHA256SUMS
status=0
while IFS= read -r file; do
  if ! grep -q "  ${file}\$" SHA256SUMS; then
    echo "data/${file}: not in data/SHA256SUMS (add it there and its provenance to data/SOURCES.md)" >&2
    status=1
  fi
  if ! grep -q "| ${file} |" SOURCES.md; then
    echo "data/${file}: not in the table of data/SOURCES.md" >&2
    status=1
  fi
done < <(find . -type f ! -path './scenarios/*' ! -path './campaigns/*' ! -name SOURCES.md ! -name SHA256SUMS | sed 's|^\./||' | sort)
[[ $status -eq 0 ]] && echo "data/: $(wc -l < SHA256SUMS) files, checksums and provenance entries complete"
exit $status
