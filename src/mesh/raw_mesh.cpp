#include "mesh/raw_mesh.hpp"

#include <cstdint>
#include <cstring>
#include <type_traits>

#include "mesh/mesh_error.hpp"

namespace fsi {
namespace {

// Parent and child are the same program image, so native byte order and sizes.
class Writer {
 public:
  template <class T>
  void scalar(T v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const char*>(&v);
    bytes_.insert(bytes_.end(), p, p + sizeof v);
  }
  template <class T>
  void array(const std::vector<T>& v) {
    scalar<std::uint64_t>(v.size());
    const auto* p = reinterpret_cast<const char*>(v.data());
    bytes_.insert(bytes_.end(), p, p + v.size() * sizeof(T));
  }
  void text(const std::string& s) { array(std::vector<char>(s.begin(), s.end())); }
  std::vector<char> take() { return std::move(bytes_); }

 private:
  std::vector<char> bytes_;
};

class Reader {
 public:
  explicit Reader(const std::vector<char>& bytes) : bytes_(bytes) {}
  template <class T>
  T scalar() {
    T v;
    need(sizeof v);
    std::memcpy(&v, bytes_.data() + at_, sizeof v);
    at_ += sizeof v;
    return v;
  }
  template <class T>
  std::vector<T> array() {
    const auto n = scalar<std::uint64_t>();
    if (n > (bytes_.size() - at_) / sizeof(T)) fail();
    std::vector<T> v(n);
    if (n > 0) std::memcpy(v.data(), bytes_.data() + at_, n * sizeof(T));  // data() may be null
    at_ += n * sizeof(T);
    return v;
  }
  std::string text() {
    const auto v = array<char>();
    return {v.begin(), v.end()};
  }
  std::size_t count() {  // a count of records, each at least 8 bytes long
    const auto n = scalar<std::uint64_t>();
    if (n > (bytes_.size() - at_) / 8) fail();
    return n;
  }
  bool at_end() const { return at_ == bytes_.size(); }
  [[noreturn]] static void fail() {
    throw MeshError("the Gmsh child process sent a malformed reply");
  }

 private:
  void need(std::size_t n) const {
    if (n > bytes_.size() - at_) fail();
  }
  const std::vector<char>& bytes_;
  std::size_t at_ = 0;
};

}  // namespace

std::vector<char> encode(const RawMesh& raw) {
  Writer w;
  w.array(raw.node_tags);
  w.array(raw.coords);
  w.scalar<std::uint64_t>(raw.groups.size());
  for (const auto& g : raw.groups) {
    w.scalar(g.dim);
    w.text(g.name);
    w.array(g.entities);
  }
  w.scalar<std::uint64_t>(raw.elements.size());
  for (const auto& b : raw.elements) {
    for (int v : {b.dim, b.entity, b.gmsh_type, b.nodes_per_element}) w.scalar(v);
    w.array(b.tags);
    w.array(b.nodes);
  }
  w.scalar<std::uint64_t>(raw.log.size());
  for (const auto& line : raw.log) w.text(line);
  return w.take();
}

RawMesh decode(const std::vector<char>& bytes) {
  Reader r(bytes);
  RawMesh raw;
  raw.node_tags = r.array<std::size_t>();
  raw.coords = r.array<double>();
  raw.groups.resize(r.count());
  for (auto& g : raw.groups) {
    g.dim = r.scalar<int>();
    g.name = r.text();
    g.entities = r.array<int>();
  }
  raw.elements.resize(r.count());
  for (auto& b : raw.elements) {
    for (int* v : {&b.dim, &b.entity, &b.gmsh_type, &b.nodes_per_element}) *v = r.scalar<int>();
    b.tags = r.array<std::size_t>();
    b.nodes = r.array<std::size_t>();
  }
  raw.log.resize(r.count());
  for (auto& line : raw.log) line = r.text();
  if (!r.at_end()) Reader::fail();
  return raw;
}

}  // namespace fsi
