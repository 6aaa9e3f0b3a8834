// A user's Gmsh .geo script (structure.shape = "geo", SPEC §9). A script is code:
// Gmsh's language can run programs (System, SystemCall), read and write files
// (Include, Merge, Save, Print, Printf > "file", CreateDir, DeleteFile, ...) and
// stall (Sleep). A case file is data and must not reach outside the geometry, so the
// script is read here and refused if it uses any of those; the child that meshes it
// also cannot write a file or start a process (gmsh_child.hpp, forbid_side_effects).
#pragma once

#include <string>

namespace fsi {

// The largest script read (bytes): far above any hand-written geometry.
inline constexpr std::size_t kMaxGeoScriptBytes = 1u << 20;

// The text of the script at `path`. Throws MeshError "<path>: ..." if it is not a
// readable regular file named .geo of at most kMaxGeoScriptBytes, or if it uses a
// command that reaches outside the geometry ("<path>:<line>: ... 'System' ...").
std::string read_geo_script(const std::string& path);

// The same check on a script's text (`path` names it in messages).
void check_geo_script(const std::string& text, const std::string& path);

}  // namespace fsi
