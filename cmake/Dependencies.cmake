# The Debian packages fsicontact builds on (scripts/install-deps.sh installs them),
# shared by the main build and the fuzzing build (fuzz/CMakeLists.txt).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(tomlplusplus REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3.11 REQUIRED)
find_package(Boost 1.74 REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(IPOPT REQUIRED IMPORTED_TARGET ipopt)
pkg_check_modules(CAIRO REQUIRED IMPORTED_TARGET cairo)
pkg_check_modules(LIBPNG REQUIRED IMPORTED_TARGET libpng)
# muparser (libmuparser-dev): the case's expressions in x, y, t (common/expression.hpp).
pkg_check_modules(MUPARSER REQUIRED IMPORTED_TARGET muparser)
find_package(ZLIB REQUIRED)
# giflib (libgif-dev): a time run's animation (io/gif.hpp). No pkg-config file on Debian 12.
find_path(GIF_INCLUDE_DIR gif_lib.h REQUIRED)
find_library(GIF_LIBRARY gif REQUIRED)
# CGAL (libcgal-dev, header-only, with GMP and MPFR for its exact predicates): the
# constrained Delaunay triangulation and refinement of the mesh generator. Its target
# adds -frounding-math for g++, which its interval filters need (without it a
# release build crashed, measured).
set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE)
find_package(CGAL 5.5 REQUIRED)

# SuiteSparse and Gmsh ship no CMake config on Debian 12: locate them directly.
find_path(SUITESPARSE_INCLUDE_DIR umfpack.h PATH_SUFFIXES suitesparse REQUIRED)
foreach(lib umfpack cholmod amd colamd camd ccolamd suitesparseconfig)
  find_library(SUITESPARSE_${lib}_LIBRARY ${lib} REQUIRED)
  list(APPEND SUITESPARSE_LIBRARIES ${SUITESPARSE_${lib}_LIBRARY})
endforeach()
# MUMPS, sequential (libmumps-seq-dev): the fluid's symmetric indefinite direct solver.
find_path(MUMPS_INCLUDE_DIR dmumps_c.h REQUIRED)
find_library(MUMPS_LIBRARY dmumps_seq REQUIRED)
find_path(GMSH_INCLUDE_DIR gmsh.h REQUIRED)
find_library(GMSH_LIBRARY gmsh REQUIRED)


# PETSc (libpetsc-real-dev: OpenMPI, parallel MUMPS, hypre), the fluid's parallel and
# iterative linear solvers (SPEC §13), in a plugin loaded by the runs that ask for it
# (fluid/petsc_plugin.hpp). Optional: without it those runs fail naming the package.
# Not in the instrumented build: the plugin must be opened with RTLD_DEEPBIND (the
# program's sequential MUMPS brings a stub MPI_Init that PETSc would otherwise call),
# which AddressSanitizer refuses.
pkg_check_modules(PETSC IMPORTED_TARGET PETSc)
if(PETSC_FOUND)
  pkg_check_modules(MPI_C IMPORTED_TARGET mpi-c)  # PETSc's pkg-config file omits its MPI
endif()
if(PETSC_FOUND AND MPI_C_FOUND AND NOT FSICONTACT_SANITIZE AND NOT FSICONTACT_FUZZ)
  option(FSICONTACT_PETSC "Build the PETSc plugin (fluid.linear_solver = petsc-*)" ON)
else()
  set(FSICONTACT_PETSC OFF)
endif()
