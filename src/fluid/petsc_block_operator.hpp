// Inside the PETSc plugin: "petsc-iterative"'s operator K = [A_u Bᵀ; B D] applied by
// its blocks (a MATSHELL), so that K itself is not needed once its blocks are taken
// (petsc_blocks.hpp): the caller's arrays (or, on several ranks, PETSc's copy of its
// rows) are freed before the preconditioner's set-up, the memory's peak. The blocks are
// those the preconditioner holds anyway (petsc_schur.hpp): A_u (hypre's copy, on which
// its hierarchy is built), Bᵀ (its product's), and D, the pressure's block, small (a
// P1 stencil); B is Bᵀ's transpose where K is its own (StokesAssembler makes a
// symmetric K so bit for bit), a block of its own otherwise.
#pragma once

#include "fluid/petsc_blocks.hpp"
#include "fluid/petsc_field_vectors.hpp"

namespace fsi {

// op becomes the shell x ↦ K x for the blocks k (each referenced, not taken) in the
// layout of the vector `whole`, its work space v (shared). "" or the error.
std::string make_block_operator(const KBlocks& k, std::shared_ptr<FieldVectors> v, Vec whole, Mat& op);

// norm = ‖b − K x‖ for op made by make_block_operator, computed in its work space. "" or
// the error.
std::string block_residual_norm(Mat op, Vec x, Vec b, PetscReal& norm);

}  // namespace fsi
