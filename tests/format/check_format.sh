#!/usr/bin/env bash
# Fails when a C++ source of seaflex differs from what clang-format (.clang-format) makes of it.
set -euo pipefail
cd "${1:-$(dirname "$0")/../..}"
files=$(git ls-files '*.cpp' '*.hpp' 2>/dev/null || find src apps tests bench -name '*.cpp' -o -name '*.hpp')
[ -n "$files" ] || { echo "no sources found"; exit 1; }
# shellcheck disable=SC2086
if ! clang-format --dry-run --Werror $files; then
  echo "clang-format: the files above are not formatted; run: clang-format -i \$(git ls-files '*.cpp' '*.hpp')"
  exit 1
fi
echo "clang-format: $(echo "$files" | wc -w) files formatted"
