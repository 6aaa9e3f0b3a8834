// What a Gmsh child process sends back: Gmsh's data as Gmsh gives it (node tags,
// coordinates, element blocks, physical groups), checked by nobody yet. The parent
// turns it into a Mesh (mesh_builder.hpp), so that every check runs in our process,
// where sanitizers and the fuzzer see it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace fsi {

// One block of getElements(): the elements of one Gmsh type on one entity.
struct RawElements {
  int dim = 0, entity = 0, gmsh_type = 0;
  int nodes_per_element = 0;
  std::vector<std::size_t> tags;   // element tags
  std::vector<std::size_t> nodes;  // nodes_per_element node tags per element
};

// A physical group: its name and the entities it holds (merged by name).
struct RawGroup {
  int dim = 0;
  std::string name;
  std::vector<int> entities;
};

struct RawMesh {
  std::vector<std::size_t> node_tags;
  std::vector<double> coords;         // x, y, z per node, in the order of node_tags
  std::vector<RawGroup> groups;       // of dimension 1 and 2
  std::vector<RawElements> elements;  // every block of every entity of `groups`
  std::vector<std::string> log;       // what Gmsh said while reading (warnings, skips)
};

// Bytes for the pipe, and back; decode throws MeshError on malformed bytes (it
// checks every count against the bytes left before it allocates).
std::vector<char> encode(const RawMesh& raw);
RawMesh decode(const std::vector<char>& bytes);

}  // namespace fsi
