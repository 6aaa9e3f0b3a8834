#!/bin/sh
# Checks the Debian package (make package; issue 31): its contents (the program, the
# Gmsh plugin beside it, the cases with their meshes and .geo files, the man page, the
# docs), its dependencies as dpkg-shlibdeps computed them (MUMPS, Gmsh, IPOPT, ...),
# and that the program it holds runs: extracted with dpkg -x into a temporary
# directory, it runs a generated case and a .geo case there. With --install it also
# installs it (apt-get install ./fsicontact_*.deb; root) and runs
# /usr/bin/fsicontact on the installed §7.2 case.
#   scripts/check-deb.sh [--install] [BUILD_DIR]        (default build; make package first)
set -eu
install=no
if [ "${1:-}" = "--install" ]; then install=yes; shift; fi
build=${1:-build}
deb=$(ls "$build"/fsicontact_*.deb 2> /dev/null | head -1)
[ -n "$deb" ] || { echo "check-deb: no $build/fsicontact_*.deb (run make package)" >&2; exit 1; }
deb=$(cd "$(dirname "$deb")" && pwd)/$(basename "$deb")
fail() { echo "check-deb: $deb: $*" >&2; exit 1; }

contents=$(dpkg-deb -c "$deb" | awk '{print $6}')
for f in ./usr/bin/fsicontact ./usr/lib/fsicontact/libfsicontact_gmsh.so ./usr/share/man/man1/fsicontact.1 \
         ./usr/lib/python3/dist-packages/fsicontact/__init__.py \
         ./usr/share/fsicontact/cases/paper-7.2.toml ./usr/share/fsicontact/cases/geo/capsule.geo \
         ./usr/share/fsicontact/cases/meshes/paper-7.1-beam.msh ./usr/share/doc/fsicontact/README.md; do
  echo "$contents" | grep -q -x -F "$f" || fail "does not hold $f"
done
depends=$(dpkg-deb -f "$deb" Depends)
for lib in libmumps-seq libgmsh coinor-libipopt libumfpack libcholmod libcairo2 libmuparser libgif; do
  echo "$depends" | grep -q "$lib" || fail "its Depends lacks $lib: $depends"
done

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
dpkg -x "$deb" "$tmp/root"
cd "$tmp"
"$tmp/root/usr/bin/fsicontact" --version | grep -q '^fsicontact [0-9]' || fail "its program prints no version"
"$tmp/root/usr/bin/fsicontact" run "$tmp/root/usr/share/fsicontact/cases/paper-7.1-fig5-coarse.toml" --out generated -q \
  || fail "its program failed on paper-7.1-fig5-coarse.toml"
"$tmp/root/usr/bin/fsicontact" run "$tmp/root/usr/share/fsicontact/cases/capsule-against-a-wall.toml" --out geo -q \
  || fail "its program failed on capsule-against-a-wall.toml (.geo: the plugin)"

if [ "$install" = yes ]; then
  apt-get install -y "$deb" > /dev/null || fail "apt-get install failed"
  /usr/bin/fsicontact run /usr/share/fsicontact/cases/paper-7.2.toml --out installed -q || fail "/usr/bin/fsicontact failed"
  man -w fsicontact > /dev/null 2>&1 || [ -f /usr/share/man/man1/fsicontact.1 ] || fail "no man page installed"
  /usr/bin/python3 -c "import fsicontact; print(fsicontact.run('/usr/share/fsicontact/cases/paper-7.2.toml', out='installed-py').summary['max_displacement'])" \
    || fail "import fsicontact failed after the install"
fi
echo "check-deb: $(basename "$deb") holds the program, its plugin, the cases and the man page; depends on"
echo "  $depends"
echo "  and runs from its extracted tree$( [ "$install" = yes ] && echo ' and installed')."
