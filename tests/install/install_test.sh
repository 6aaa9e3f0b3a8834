#!/bin/sh
# The install (issue 31): cmake --install into a temporary prefix, the prefix then moved
# elsewhere as a whole, and the installed program run from another directory on
# installed cases: a generated one, a .geo one (the Gmsh plugin found beside the
# installed program) and a .msh one given by a relative path. Nothing installed may
# name the build tree, and without its own plugin the installed program fails saying
# where it looked, never falling back to the build's.
#   install_test.sh BUILD_DIR
set -eu
build=$(cd "$1" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "install_test: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$tmp/first" > /dev/null
mv "$tmp/first" "$tmp/moved"
P="$tmp/moved"
for f in bin/fsicontact lib/fsicontact/libfsicontact_gmsh.so share/man/man1/fsicontact.1 \
         share/fsicontact/cases/paper-7.2.toml share/fsicontact/cases/geo/capsule.geo \
         share/fsicontact/cases/meshes/paper-7.1-beam.msh share/doc/fsicontact/README.md; do
  [ -f "$P/$f" ] || fail "$f is not installed"
done
if grep -q -F "$build" "$P/bin/fsicontact" "$P/lib/fsicontact/libfsicontact_gmsh.so"; then
  fail "the installed program or plugin names the build tree $build"
fi
head -1 "$P/share/man/man1/fsicontact.1" | grep -q '^\.TH FSICONTACT 1' || fail "the man page has no .TH line"

mkdir "$tmp/elsewhere" && cd "$tmp/elsewhere"
"$P/bin/fsicontact" --version | grep -q '^fsicontact [0-9]' || fail "--version says no version"
"$P/bin/fsicontact" run "$P/share/fsicontact/cases/paper-7.1-fig5-coarse.toml" --out generated -q \
  || fail "the generated case failed"
"$P/bin/fsicontact" run "$P/share/fsicontact/cases/capsule-against-a-wall.toml" --out geo -q \
  || fail "the .geo case failed"
(cd "$P/share/fsicontact" && "$P/bin/fsicontact" run cases/paper-7.1-fig5-msh.toml --out "$tmp/elsewhere/msh" -q) \
  || fail "the .msh case by a relative path failed"
for run in generated geo msh; do
  grep -q '"status": "converged"' "$run/summary.json" || fail "$run/summary.json is not converged"
  grep -q '"program"' "$run/summary.json" || fail "$run/summary.json has no \"program\""
done

# The Python module from the moved prefix, the Gmsh plugin found from it too (a .geo case).
if [ -d "$P/lib/python3/dist-packages/fsicontact" ]; then
  PYTHONPATH="$P/lib/python3/dist-packages" /usr/bin/python3 -c "
import fsicontact, sys
r = fsicontact.run('$P/share/fsicontact/cases/capsule-against-a-wall.toml', out='$tmp/elsewhere/py')
sys.exit(0 if r.converged and r.summary['max_displacement'] > 0 else 1)" || fail "the installed Python module failed"
fi

# Without its plugin: a failure naming where it looked (exit 1), not the build's plugin.
rm "$P/lib/fsicontact/libfsicontact_gmsh.so"
status=0
"$P/bin/fsicontact" run "$P/share/fsicontact/cases/capsule-against-a-wall.toml" --out noplugin -q 2> err.txt || status=$?
[ "$status" -eq 1 ] || fail "without the plugin the .geo case exited $status, not 1"
grep -q -F "$P/bin/../lib/fsicontact/libfsicontact_gmsh.so" err.txt || fail "the error does not say where it looked: $(cat err.txt)"
echo "install_test: installed, moved and run from $P"
