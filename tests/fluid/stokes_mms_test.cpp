// Manufactured Stokes solutions for the mini element (χ = 0): v = curl of a stream
// function (divergence-free), a smooth pressure, f = −μΔv + ∇p, v prescribed on the
// Dirichlet parts and the exact traction σ(v,p)n on the natural part, as in the
// paper's box (outlet at the bottom). Theory: velocity O(h²) in L², O(h) in H¹,
// pressure at least O(h) in L².
#include <gtest/gtest.h>

#include <numbers>

#include "mesh/generated_mesh.hpp"
#include "mesh/gmsh_io.hpp"
#include "support/norms.hpp"
#include "support/stokes_mms.hpp"
#include "support/stokes_norms.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::stokes_mms_test {
namespace {

using testing::stokes_mms::solve;

void check_rates(const std::vector<double>& h, const std::vector<testing::StokesErrors>& e,
                 bool pairwise) {
  std::vector<double> lh, lv, lg, lp;
  for (std::size_t k = 0; k < h.size(); ++k) {
    lh.push_back(std::log(h[k]));
    lv.push_back(std::log(e[k].v_l2));
    lg.push_back(std::log(e[k].v_h1));
    lp.push_back(std::log(e[k].p_l2));
    std::printf("h %.4f  |v|L2 %.3e  |v|H1 %.3e  |p|L2 %.3e\n", h[k], e[k].v_l2, e[k].v_h1, e[k].p_l2);
  }
  auto check = [](double rv, double rg, double rp, const std::string& what) {
    std::printf("%s: velocity L2 %.2f, H1 %.2f, pressure L2 %.2f\n", what.c_str(), rv, rg, rp);
    EXPECT_GE(rv, 1.8) << what;
    EXPECT_GE(rg, 0.9) << what;
    EXPECT_GE(rp, 0.9) << what;
  };
  if (pairwise) {
    for (std::size_t k = 0; k + 1 < h.size(); ++k)
      check(testing::rate(e[k].v_l2, e[k + 1].v_l2, h[k], h[k + 1]),
            testing::rate(e[k].v_h1, e[k + 1].v_h1, h[k], h[k + 1]),
            testing::rate(e[k].p_l2, e[k + 1].p_l2, h[k], h[k + 1]), "refinement " + std::to_string(k));
  } else {
    check(testing::fitted_slope(lh, lv), testing::fitted_slope(lh, lg), testing::fitted_slope(lh, lp),
          "fitted");
  }
}

// Unit square, nested structured meshes: Dirichlet left, right, top; outlet bottom.
TEST(StokesMms, UnitSquareConvergesAtMiniElementRates) {
  std::vector<double> h;
  std::vector<testing::StokesErrors> e;
  for (int n : {8, 16, 32, 64}) {
    const Mesh mesh = testing::structured_rectangle(1.0, 1.0, n, n);
    h.push_back(1.0 / n);
    e.push_back(solve(mesh, {"left", "right", "top"}, "bottom"));
  }
  check_rates(h, e, true);
}

// The paper's topology: a box with a circular hole (no-slip hole, outlet at the
// bottom), the generated (unstructured) meshes: rates fitted over the sequence.
TEST(StokesMms, BoxWithHoleConvergesAtMiniElementRates) {
  std::vector<double> h;
  std::vector<testing::StokesErrors> e;
  for (double size : {0.1, 0.05, 0.025, 0.0125}) {
    const Mesh mesh = generate_fluid_mesh({1.0, 0.5, 0.5, 0.5, 0.05, 0.2, size});
    h.push_back(testing::mesh_size(mesh));
    e.push_back(solve(mesh, {"Sigma_1", "Sigma_3", "Sigma_4", "Sigma_5"}, "Sigma_2"));
  }
  check_rates(h, e, false);
}

}  // namespace
}  // namespace fsi::stokes_mms_test
