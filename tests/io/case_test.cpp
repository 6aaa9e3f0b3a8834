// The case loader: defaults, overrides, the resolved TOML, and every input the
// fuzzer ever crashed on (tests/data/fuzz-regressions/).
#include "io/case.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"

namespace fsi::case_test {
namespace {

TEST(Case, DefaultsAreThePapersSection72) {
  const Case c = load_case("");
  ASSERT_TRUE(c.fluid.has_value());
  EXPECT_EQ(c.name, "paper-7.2");
  EXPECT_EQ(c.structure.L, 0.3);
  EXPECT_EQ(c.structure.H, 0.03);
  EXPECT_EQ(c.structure.E, 3.0e5);
  EXPECT_EQ(c.structure.nu, 0.45);
  EXPECT_DOUBLE_EQ(c.structure.f.y(), -9.81 * 1100);
  EXPECT_EQ(c.structure.h, 0.015);
  EXPECT_EQ(c.obstacle.x0, 0.2);
  EXPECT_EQ(c.obstacle.y0, -0.07);
  EXPECT_EQ(c.obstacle.r, 0.05);
  EXPECT_EQ(c.obstacle.gamma, 0.8);
  EXPECT_EQ(c.fluid->L1, 0.41);
  EXPECT_EQ(c.fluid->mu, 0.0035);
  EXPECT_DOUBLE_EQ(c.fluid->f.y(), -9.81 * 100);
  EXPECT_EQ(c.fluid->Vmax, 8.0);
  EXPECT_EQ(c.fluid->h, 0.01);
  EXPECT_EQ(c.coupling.eps, 1e-5);
  EXPECT_EQ(c.coupling.omega, 0.1);
  EXPECT_EQ(c.coupling.tol, 1e-4);
  EXPECT_EQ(c.coupling.max_iterations, 100);
  EXPECT_EQ(c.coupling.scheme, "constant");
  EXPECT_EQ(c.contact.solver, "active-set");
  EXPECT_EQ(c.output.dir, "out/paper-7.2");
}

TEST(Case, TheShippedSection72FileEqualsTheBuiltInDefault) {
  const Case file = load_case(std::string(FSICONTACT_SOURCE_DIR) + "/cases/paper-7.2.toml");
  Case builtin = load_case("");
  builtin.source = file.source;
  EXPECT_EQ(to_toml(file), to_toml(builtin));
}

TEST(Case, WithoutAFluidSectionIsContactOnly) {
  const Case c = load_case_text("name = \"x\"\n[structure]\nL = 0.06\nH = 0.005\nh = 0.001\n[obstacle]\nx0 = 0.055\ny0 = -0.012\nr = 0.005\n", "x.toml");
  EXPECT_FALSE(c.fluid.has_value());
  EXPECT_EQ(c.structure.L, 0.06);
}

TEST(Case, OverridesTakeTomlValuesOrBareWords) {
  const Case c = load_case("", {"coupling.scheme=aitken", "coupling.eps=1e-4", "structure.f=[0, -5]",
                                "coupling.max_iterations=7", "output.png=false", "name=\"other\""});
  EXPECT_EQ(c.coupling.scheme, "aitken");
  EXPECT_EQ(c.coupling.eps, 1e-4);
  EXPECT_EQ(c.structure.f.y(), -5.0);
  EXPECT_EQ(c.coupling.max_iterations, 7);
  EXPECT_FALSE(c.output.png);
}

// eps_rule = "layer" (issue 27): ε = (h/2)²/μ_F from the fluid's size at the
// structure (h_near where there is a band), in a single run too; a stated ε must be
// that one, so a resolved case written back loads again, and any other is refused.
TEST(Case, TheLayerRuleSetsEpsFromTheSizeAtTheStructure) {
  const Case plain = load_case("", {"fluid.h=0.004", "coupling.eps_rule=layer"});
  EXPECT_NEAR(plain.coupling.eps, 0.002 * 0.002 / 0.0035, 1e-18);
  EXPECT_EQ(plain.coupling.eps_power(), 2.0);
  const Case band = load_case("", {"fluid.h_near=0.001", "coupling.eps_rule=layer", "fluid.mu=0.01"});
  EXPECT_NEAR(band.coupling.eps, 0.0005 * 0.0005 / 0.01, 1e-18);
  EXPECT_EQ(to_toml(load_case_text(to_toml(band), "again.toml")), to_toml(band));
  try {
    load_case("", {"coupling.eps_rule=layer", "coupling.eps=1e-5"});
    FAIL() << "a contradicting ε was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("coupling.eps = 1e-05 contradicts coupling.eps_rule = \"layer\""),
              std::string::npos) << e.what();
  }
  try {  // ε below the key's own range
    load_case("", {"coupling.eps_rule=layer", "fluid.mu=1e20"});
    FAIL() << "ε = 2.5e-25 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("coupling.eps_rule = \"layer\" gives ε = 2.5e-25"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(load_case("").coupling.eps_rule_given);
  EXPECT_TRUE(plain.coupling.eps_rule_given);
  // Eq. (33) sampled on sub-triangles no wider than the layer: ⌈hS / layer⌉, at most 8.
  EXPECT_EQ(load_case("", {"coupling.eps_rule=layer"}).coupling.force_sampling, 3);  // 0.015 / 0.005
  EXPECT_EQ(plain.coupling.force_sampling, 8);                                         // ⌈0.015 / 0.002⌉
  EXPECT_EQ(band.coupling.force_sampling, 8);                                          // 30, at most 8
  EXPECT_EQ(load_case("", {"coupling.eps_rule=layer", "structure.h=0.01"}).coupling.force_sampling, 2);
  for (const std::vector<std::string>& kept : std::vector<std::vector<std::string>>{
           {"coupling.force_sampling=1"}, {"structure.element=P2"}, {"fluid.method=body-fitted"}}) {
    std::vector<std::string> sets = kept;
    sets.push_back("coupling.eps_rule=layer");
    EXPECT_EQ(load_case("", sets).coupling.force_sampling, 1) << kept[0];
  }
}

// coupling.force_sampling (issue 27): 1 to 8, for the penalised fluid on a P1 structure.
TEST(Case, ForceSamplingIsForThePenalisedFluidOnAP1Structure) {
  const Case c = load_case("", {"coupling.force_sampling=3"});
  EXPECT_EQ(c.coupling.force_sampling, 3);
  EXPECT_EQ(to_toml(load_case_text(to_toml(c), "again.toml")), to_toml(c));
  EXPECT_EQ(load_case("").coupling.force_sampling, 1);
  for (const std::vector<std::string>& sets :
       {std::vector<std::string>{"coupling.force_sampling=9"}, {"coupling.force_sampling=0"},
        {"coupling.force_sampling=2", "fluid.method=body-fitted"}, {"coupling.force_sampling=2", "structure.element=P2"}})
    try {
      load_case("", sets);
      FAIL() << sets.front() << " accepted with " << sets.back();
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("coupling.force_sampling"), std::string::npos) << e.what();
    }
}

TEST(Case, TheBandIsAWidthOrABoxAndEpsRulesHaveAPower) {
  const Case width = load_case("", {"fluid.h_near=0.002", "fluid.band=0.03", "coupling.eps_rule=h^1.5"});
  EXPECT_EQ(width.fluid->h_near, 0.002);
  EXPECT_EQ(width.fluid->band, 0.03);
  EXPECT_FALSE(width.fluid->band_box);
  EXPECT_EQ(width.coupling.eps_power(), 1.5);
  const Case box = load_case("", {"fluid.band=[0, -0.06, 0.33, 0.05]"});
  ASSERT_TRUE(box.fluid->band_box);
  EXPECT_EQ((*box.fluid->band_box)[3], 0.05);
  EXPECT_EQ(box.coupling.eps_power(), 0.0);
  EXPECT_EQ(box.fluid->size_near(), box.fluid->h);  // no band: hF at the structure
  for (const Case& c : {width, box}) EXPECT_EQ(to_toml(load_case_text(to_toml(c), "again.toml")), to_toml(c));
}

// SPEC §10 "Box sides": the paper's by default, each side set by its key, kept in
// the resolved TOML and accepted by --set.
TEST(Case, BoxSidesDefaultToThePapersAndRoundTrip) {
  const Case paper = load_case("");
  EXPECT_EQ(paper.fluid->sides, (std::array<std::string, 4>{"wall", "outflow", "wall", "inflow"}));
  const Case channel = load_case("", {"fluid.left=outflow", "fluid.bottom=wall", "fluid.right=inflow", "fluid.top=wall"});
  EXPECT_EQ(channel.fluid->sides, (std::array<std::string, 4>{"outflow", "wall", "inflow", "wall"}));
  const std::string text = to_toml(channel);
  EXPECT_NE(text.find("right = 'inflow'"), std::string::npos) << text;
  EXPECT_EQ(load_case_text(text, "again.toml").fluid->sides, channel.fluid->sides);
  const std::vector<std::string> keys = case_keys();
  for (const char* side : kBoxSideKeys)
    EXPECT_NE(std::find(keys.begin(), keys.end(), std::string("fluid.") + side), keys.end()) << side;
}

// Refused: an unknown condition, and a box without an outflow side (the pressure is
// then fixed only up to a constant, and an inflow could not balance).
TEST(Case, BoxSidesRefuseUnknownValuesAndBoxesWithoutAnOutflow) {
  const auto message = [](const std::vector<std::string>& sets) {
    try {
      load_case("", sets);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({"fluid.left=open"}),
            "--set fluid.left: fluid.left = \"open\" is not a known choice; allowed: \"wall\", \"inflow\", \"outflow\"");
  const std::string closed = message({"fluid.bottom=wall"});
  EXPECT_EQ(closed.rfind("(built-in paper-7.2 case): fluid.top leaves the fluid box without an outflow side", 0), 0u) << closed;
  EXPECT_NE(closed.find("allowed: at least one of fluid.left, fluid.bottom, fluid.right, fluid.top = \"outflow\""),
            std::string::npos) << closed;
  const std::string walls = message({"fluid.bottom=wall", "fluid.top=wall"});
  EXPECT_EQ(walls.rfind("--set fluid.bottom: fluid.bottom leaves", 0), 0u) << walls;
  EXPECT_EQ(walls.find("the inflow"), std::string::npos) << walls;
  EXPECT_EQ(message({"fluid.bottom=wall", "fluid.top=outflow"}), "no error");  // an outflow, no inflow
}

// fluid.element: "mini" by default; "taylor-hood" for the fluid alone, with Newton's
// method in time; refused with a structure, and an unknown name, by key and choices.
TEST(Case, TheTaylorHoodElementIsForTheFluidAlone) {
  const auto message = [](const std::string& file, const std::vector<std::string>& sets) {
    try {
      load_case(file, sets);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(load_case("", {}).fluid->element, "mini");
  const std::string dfg = std::string(FSICONTACT_SOURCE_DIR) + "/cases/dfg-2d2.toml";
  EXPECT_EQ(message(dfg, {"fluid.element=taylor-hood"}), "no error");
  EXPECT_EQ(load_case(dfg, {"fluid.element=taylor-hood"}).fluid->element, "taylor-hood");
  EXPECT_EQ(message("", {"fluid.element=p2p1"}), "--set fluid.element: fluid.element = \"p2p1\" is not a known "
                                                 "choice; allowed: \"mini\", \"taylor-hood\"");
  const std::string coupled = message("", {"fluid.element=taylor-hood"});
  EXPECT_NE(coupled.find("fluid.element = \"taylor-hood\" solves the fluid alone so far"), std::string::npos) << coupled;
  EXPECT_NE(coupled.find("allowed: \"mini\" with a structure"), std::string::npos) << coupled;
  const std::string lagged = message(dfg, {"fluid.element=taylor-hood", "time.convection=semi-implicit"});
  EXPECT_NE(lagged.find("time.convection = \"semi-implicit\""), std::string::npos) << lagged;
  EXPECT_NE(lagged.find("allowed: \"implicit\" with fluid.element = \"taylor-hood\""), std::string::npos) << lagged;
}

TEST(Case, IntegersAreAcceptedForRealKeys) {
  const Case c = load_case("", {"structure.E=300000", "fluid.Vmax=8"});
  EXPECT_EQ(c.structure.E, 3e5);
}

TEST(Case, ResolvedTomlReloadsToTheSameCase) {
  for (const char* name : {"paper-7.2", "paper-7.1-fig7-fine", "paper-7.1-fig5-msh", "flap-against-a-wedge"}) {
    const Case c = load_case(std::string(FSICONTACT_SOURCE_DIR) + "/cases/" + name + ".toml");
    const std::string text = to_toml(c);
    EXPECT_EQ(to_toml(load_case_text(text, "resolved.toml")), text) << name;
  }
}

TEST(Case, ErrorsNameTheKeyAndTheAllowedRange) {
  try {
    load_case("", {"structure.nu=0.7"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("--set structure.nu"), std::string::npos) << m;
    EXPECT_NE(m.find("0.7"), std::string::npos) << m;
    EXPECT_NE(m.find("allowed: [0, 0.499999995]"), std::string::npos) << m;
  }
}

// Every input the fuzzer (fuzz/fuzz_case.cpp) crashed on: now a Case or an InputError.
TEST(Case, FuzzRegressionsGiveACaseOrAnInputError) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(FSICONTACT_SOURCE_DIR) + "/tests/data/fuzz-regressions")) {
    if (entry.path().extension() != ".toml") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    try {
      load_case_text(text.str(), entry.path().filename().string());
    } catch (const InputError&) {
    }
    ++files;
  }
  EXPECT_GE(files, 1);
}

}  // namespace
}  // namespace fsi::case_test

namespace fsi::case_test {
namespace {

// Every shipped case reloads to itself from its resolved TOML, bit for bit (the
// contract fuzz_case checks; a half-plane's normal, normalised twice, broke it).
TEST(Case, EveryShippedCaseRoundTripsThroughItsResolvedToml) {
  int cases = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::string(FSICONTACT_SOURCE_DIR) + "/cases")) {
    if (e.path().extension() != ".toml") continue;
    const Case c = load_case(e.path().string());
    const std::string resolved = to_toml(c);
    EXPECT_EQ(to_toml(load_case_text(resolved, "resolved.toml")), resolved) << e.path();
    ++cases;
  }
  EXPECT_GE(cases, 15);
  const Case tilted = load_case_text("[[obstacles]]\nshape = \"half-plane\"\npoint = [0, -1]\nnormal = [-0.2, 1.0]\n"
                                     "[contact]\ngap = \"normal\"\nboundary = \"all\"\n", "t.toml");
  EXPECT_EQ(tilted.obstacles[0].normal.x(), -0.2);  // as given
}

// output.probes (SPEC §11): none by default, kept in order as given, and written back
// so that the resolved case.toml reruns with the same probes.
TEST(Case, ProbesRoundTripInTheirOrder) {
  EXPECT_TRUE(load_case("").output.probes.empty());
  EXPECT_EQ(to_toml(load_case("")).find("probes"), std::string::npos);  // none: the key is not written
  const Case c = load_case_text("[output]\nprobes = [[0.3, 0.015], [0.1, 1e-3], [0, 0]]\n", "p.toml");
  ASSERT_EQ(c.output.probes.size(), 3u);
  EXPECT_EQ(c.output.probes[0], Point(0.3, 0.015));
  EXPECT_EQ(c.output.probes[1], Point(0.1, 1e-3));
  EXPECT_EQ(c.output.probes[2], Point(0, 0));
  const std::string resolved = to_toml(c);
  const Case again = load_case_text(resolved, "resolved.toml");
  EXPECT_EQ(again.output.probes, c.output.probes);
  EXPECT_EQ(to_toml(again), resolved);
  const Case empty = load_case_text("[output]\nprobes = []\n", "p.toml");
  EXPECT_TRUE(empty.output.probes.empty());
}

}  // namespace
}  // namespace fsi::case_test
