// Inside the PETSc plugin (petsc_plugin.cpp and the petsc_*.cpp beside it): a PETSc
// call's error returned as text from the enclosing function, never thrown across the
// library's edge.
#pragma once

#include <petscsys.h>

#include <string>

namespace fsi {

// "PETSc: <call>: <PETSc's message>: <the first message of the error, where>".
std::string petsc_error_text(PetscErrorCode code, const char* call);

}  // namespace fsi

#define FSI_TRY(call)                                      \
  do {                                                     \
    const PetscErrorCode code_ = (call);                   \
    if (code_) return ::fsi::petsc_error_text(code_, #call); \
  } while (0)
