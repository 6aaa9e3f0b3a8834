// Which bilinear form the viscous term takes (SPEC §10 fluid.viscous_form): the
// symmetric 2μ ε:ε of the paper (traction-free outflow σn = 0) or the gradient μ∇:∇
// (the "do-nothing" outflow μ∂_n v − p n = 0 of the DFG benchmarks). Every element
// (mini, Taylor–Hood) offers both.
#pragma once

namespace fsi {

enum class ViscousForm { symmetric, gradient };

}  // namespace fsi
