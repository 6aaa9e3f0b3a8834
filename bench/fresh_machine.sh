#!/usr/bin/env bash
# The README's two commands as a newcomer meets them (docs/performance.md, "Build and test
# budgets"): removes the library packages scripts/install-deps.sh installs (and what only
# they needed) and empties apt's cache, so that every package is downloaded again; clones
# the repository's HEAD into DIR; then times `make demo` and `make test` there.
#   bench/fresh_machine.sh --yes-remove-packages [DIR]     (DIR default /tmp/fsicontact-fresh)
# It changes the machine's packages (make demo installs them again): run it on a
# throw-away machine, as root or with sudo. About 4 minutes on 2 cores.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [[ "${1:-}" != "--yes-remove-packages" ]]; then sed -n '2,8p' "$0" >&2; exit 2; fi
dir=${2:-/tmp/fsicontact-fresh}
packages=(libeigen3-dev libsuitesparse-dev libmumps-seq-dev libopenblas0-serial libgmsh-dev libcgal-dev
          coinor-libipopt-dev libtomlplusplus-dev libcli11-dev libcairo2-dev nlohmann-json3-dev libboost-dev)
sudo=$([[ $(id -u) == 0 ]] || echo sudo)
$sudo apt-get remove -y "${packages[@]}" > /dev/null
$sudo apt-get autoremove -y > /dev/null
$sudo apt-get clean
rm -rf "$dir"
git clone -q "$root" "$dir"
cd "$dir"
for target in demo test; do
  t0=$(date +%s)
  make "$target" > "make-$target.log" 2>&1 || { echo "make $target failed: $dir/make-$target.log" >&2; exit 1; }
  echo "make $target: $(($(date +%s) - t0)) s ($dir/make-$target.log)"
done
