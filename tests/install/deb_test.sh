#!/bin/sh
# The Debian package (issue 31): CPack run on the build into a temporary directory,
# then scripts/check-deb.sh on it (contents, dependencies, its program run from the
# extracted tree).
#   deb_test.sh SOURCE_DIR BUILD_DIR
set -eu
source=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
cpack -G DEB -B "$tmp" --config "$build/CPackConfig.cmake" > cpack.log 2>&1 || { cat cpack.log >&2; exit 1; }
"$source/scripts/check-deb.sh" "$tmp"
