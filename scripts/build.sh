#!/usr/bin/env bash
# Installs what is missing, then configures and builds impulse (Release) into build/: the program,
# impulse-respond and the Python package. With --tests, the test tools and every test as well
# (scripts/test.sh builds so).
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in
  "") setup=() testing=OFF ;;
  --tests) setup=(--tests) testing=ON ;;
  *) echo "build: unknown argument '$1'; run build.sh (the program and the Python package) or build.sh --tests (and the tests)" >&2; exit 1 ;;
esac
./scripts/setup.sh "${setup[@]}"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING="$testing" >/dev/null
cmake --build build -j"$(nproc)"
