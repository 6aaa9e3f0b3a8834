#!/usr/bin/env bash
# Installs the Debian packages fsicontact needs to build, test and run.
# Quiet and fast when everything is present: only missing packages reach apt.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  ninja-build            # the build tool the Makefile picks when present (no-op rebuilds 10x faster)
  libeigen3-dev          # dense/sparse linear algebra
  libsuitesparse-dev     # UMFPACK, CHOLMOD (through Eigen's wrappers)
  libmumps-seq-dev       # MUMPS, sequential: the fluid's direct solver
  libpetsc-real-dev      # PETSc (OpenMPI, parallel MUMPS, hypre): fluid.linear_solver = "petsc-*", a plugin
  openmpi-bin            # mpiexec: runs on several ranks (SPEC §13) and the two-rank tests (ctest Mpi.*)
  libopenblas0-serial    # optimised BLAS (becomes the system's libblas.so.3): 2-3x faster
                         # factorisations than the reference BLAS (docs/performance.md);
                         # serial, so results do not depend on a thread count
  libgmsh-dev            # Gmsh SDK: .geo scripts, .msh reading, body-fitted meshes
  libcgal-dev            # CGAL: constrained Delaunay triangulation of the mesh generator
  coinor-libipopt-dev    # IPOPT, the paper's QP solver
  libtomlplusplus-dev    # case files
  libmuparser-dev        # expressions in case files (fluid.Vmax, fluid.f, structure.f)
  libcli11-dev           # command line
  libcairo2-dev          # PNG figures (drawn by Cairo)
  libpng-dev zlib1g-dev  # PNG encoding, compressed VTU arrays
  libgif-dev             # a time run's animation (animation.gif)
  nlohmann-json3-dev     # summary.json
  libboost-dev           # Boost.Geometry R-tree (point location)
  libgtest-dev libbenchmark-dev
  clang libclang-rt-14-dev # the instrumented build: sanitizers and libFuzzer (make check-instrumented)
  time                   # /usr/bin/time -v: peak memory in the benchmarks
  python3                # the man page from the program's help (scripts/manpage.py), the scripts
  python3-dev pybind11-dev python3-numpy python3-pytest  # the Python module (python/) and its tests
  python3-matplotlib     # examples/python's plots
  dpkg-dev               # dpkg-shlibdeps: the .deb's dependencies (make package)
)
if [[ "${1:-}" == "--with-freefem" ]]; then
  packages+=(freefem++ libfreefem++ time)   # only for bench-compare
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "install-deps: installing ${missing[*]}" >&2
SUDO=""
[[ $(id -u) -ne 0 ]] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
