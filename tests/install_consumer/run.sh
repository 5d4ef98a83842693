#!/usr/bin/env bash
# Installs the build into a fresh prefix, then configures, builds and runs the outside project of
# this folder against that prefix alone, and imports the installed Python package (when PYTHON is
# given). Fails if the installed CMake files name the source tree.
# Usage: run.sh BUILD_DIR SOURCE_DIR WORK_DIR [PYTHON]
set -euo pipefail
build=$1 source=$2 work=$3 python=${4:-}
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log" 2>&1 || { cat "$work/install.log"; exit 1; }
if grep -rl -- "$source/src" "$work/prefix/lib/cmake/visors"; then
  echo "error: the installed package names the source tree ($source/src)" >&2
  exit 1
fi
cmake -S "$source/tests/install_consumer" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix"
cmake --build "$work/build"
"$work/build/consumer"
if [[ -n "$python" ]]; then
  (cd "$work" && PYTHONPATH="$work/prefix/lib/python3/dist-packages" "$python" -c \
    "import visors; assert visors.__file__.startswith('$work/prefix'), visors.__file__; print('python: visors', visors.__version__, 'from', visors.__file__)")
fi
