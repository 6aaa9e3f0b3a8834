#include "run/setup_cache.hpp"

#include <sstream>

namespace fsi {
namespace {

template <class... T>
std::string key_of(const T&... parts) {
  std::ostringstream s;
  s.precision(17);
  ((s << parts << '|'), ...);
  return s.str();
}

}  // namespace

std::string structure_mesh_key(const Case& c) {
  const auto& s = c.structure;
  return key_of(s.mesh, s.L, s.H, c.obstacle.xc_min(), c.obstacle.xc_max(), s.h);
}

std::string fluid_mesh_key(const Case& c) {
  const auto& f = *c.fluid;
  const auto& o = c.obstacle;
  return key_of(f.mesh, f.L1, f.H1, f.H2, o.x0, o.y0, o.r, f.h);
}

const Mesh& SetupCache::structure_mesh(const Case& c) {
  const std::string key = structure_mesh_key(c);
  auto it = structure_meshes_.find(key);
  if (it == structure_meshes_.end()) it = structure_meshes_.emplace(key, make_structure_mesh(c)).first;
  return it->second;
}

const Mesh& SetupCache::fluid_mesh(const Case& c) {
  const std::string key = fluid_mesh_key(c);
  auto it = fluid_meshes_.find(key);
  if (it == fluid_meshes_.end()) it = fluid_meshes_.emplace(key, make_fluid_mesh(c)).first;
  return it->second;
}

StructureSetup& SetupCache::structure(const Case& c) {
  const auto& s = c.structure;
  const auto& o = c.obstacle;
  const std::string key = key_of(structure_mesh_key(c), s.E, s.nu, s.f.x(), s.f.y(), s.h_N.x(), s.h_N.y(),
                                 o.x0, o.y0, o.r, c.contact.solver);
  if (key != structure_key_ || !structure_.solver) {
    structure_ = make_structure(c, structure_mesh(c), nullptr);
    structure_key_ = key;
    ++misses;
  } else {
    ++hits;
  }
  return structure_;
}

FluidSetup& SetupCache::fluid(const Case& c) {
  const auto& f = *c.fluid;
  const std::string key = key_of(fluid_mesh_key(c), f.mu, f.f.x(), f.f.y(), f.Vmax, f.chi);
  if (key != fluid_key_ || !fluid_.stokes) {
    fluid_ = FluidSetup{};  // release the old factorisation before building the next
    fluid_ = make_fluid(c, fluid_mesh(c), c.coupling.eps);
    fluid_key_ = key;
    ++misses;
  } else {
    fluid_.stokes->reset();
    fluid_.stokes->set_eps(c.coupling.eps);
    ++hits;
  }
  return fluid_;
}

}  // namespace fsi
