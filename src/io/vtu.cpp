#include "io/vtu.hpp"

#include <zlib.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "common/format.hpp"
#include "io/atomic_file.hpp"

namespace fsi {

VtuFormat vtu_format(const std::string& name) {
  if (name == "binary") return VtuFormat::binary;
  if (name == "zlib") return VtuFormat::zlib;
  if (name == "ascii") return VtuFormat::ascii;
  throw std::invalid_argument("\"binary\", \"zlib\" or \"ascii\"");
}

VtuField vector_field(const std::string& name, const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                      bool on_cells) {
  VtuField f{name, 3, {}, on_cells};
  f.values.reserve(3 * x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) f.values.insert(f.values.end(), {x[i], y[i], 0.0});
  return f;
}

VtuField scalar_field(const std::string& name, const Eigen::VectorXd& v, bool on_cells) {
  return {name, 1, std::vector<double>(v.data(), v.data() + v.size()), on_cells};
}

namespace {

static_assert(std::endian::native == std::endian::little,
              "the VTU files say byte_order=\"LittleEndian\"");

// One DataArray: its attributes and its values as bytes (Float64, Int32 or UInt8).
struct DataArray {
  std::string type, name;
  int components = 1;
  std::string bytes;
  std::string ascii;  // the same values as text, for VtuFormat::ascii
};

template <class T>
DataArray array_of(const std::string& type, const std::string& name, int components,
                   const std::vector<T>& values, VtuFormat format) {
  DataArray a{type, name, components, {}, {}};
  if (format != VtuFormat::ascii) {
    a.bytes.resize(values.size() * sizeof(T));
    std::memcpy(a.bytes.data(), values.data(), a.bytes.size());
    return a;
  }
  std::ostringstream out;
  out << std::setprecision(17);
  for (std::size_t i = 0; i < values.size(); ++i)
    out << +values[i] << ((i + 1) % static_cast<std::size_t>(components) == 0 ? '\n' : ' ');
  a.ascii = out.str();
  return a;
}

void append_u64(std::string& out, std::uint64_t n) {
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
}

// VTK's appended block: [UInt64 byte count][bytes], or for zlib [number of blocks,
// block size, size of the last block, each block's compressed size][the compressed
// blocks] (vtkZLibDataCompressor; blocks of 32 KiB as VTK writes them).
void append_block(std::string& out, const std::string& bytes, VtuFormat format) {
  if (format == VtuFormat::binary) {
    append_u64(out, bytes.size());
    out += bytes;
    return;
  }
  constexpr std::size_t kBlock = 32768;
  const std::size_t blocks = bytes.empty() ? 0 : (bytes.size() + kBlock - 1) / kBlock;
  std::vector<std::string> compressed(blocks);
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t n = std::min(kBlock, bytes.size() - b * kBlock);
    uLongf size = compressBound(static_cast<uLong>(n));
    compressed[b].resize(size);
    // Level 1: doubles compress little whatever the level (measured, docs/performance.md).
    if (compress2(reinterpret_cast<Bytef*>(compressed[b].data()), &size,
                  reinterpret_cast<const Bytef*>(bytes.data() + b * kBlock), static_cast<uLong>(n),
                  1) != Z_OK)
      throw std::runtime_error("zlib failed to compress a VTU array");
    compressed[b].resize(size);
  }
  append_u64(out, blocks);
  append_u64(out, kBlock);
  append_u64(out, blocks ? bytes.size() - (blocks - 1) * kBlock : 0);
  for (const auto& c : compressed) append_u64(out, c.size());
  for (const auto& c : compressed) out += c;
}

// The XML of one array: inline text (ascii) or a reference into the appended data.
void describe(std::string& xml, const DataArray& a, VtuFormat format, std::size_t offset) {
  xml += "<DataArray type=\"" + a.type + "\"";
  if (!a.name.empty()) xml += " Name=\"" + a.name + "\"";
  if (a.components != 1) xml += " NumberOfComponents=\"" + std::to_string(a.components) + "\"";
  if (format == VtuFormat::ascii) {
    xml += " format=\"ascii\">\n" + a.ascii + "</DataArray>\n";
  } else {
    xml += " format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
  }
}

// One piece: the points, `nodes_per_cell` point indices a cell (flat), its VTK type.
void write_piece(const std::string& path, const std::vector<Point>& points,
                 const std::vector<int>& connectivity, int nodes_per_cell, int vtk_type,
                 const std::vector<VtuField>& fields, VtuFormat format) {
  const int nv = static_cast<int>(points.size());
  const int nt = static_cast<int>(connectivity.size()) / nodes_per_cell;
  for (const auto& f : fields)
    if (f.values.size() != static_cast<std::size_t>((f.on_cells ? nt : nv) * f.components))
      throw std::logic_error("vtu field '" + f.name + "' has the wrong size");
  std::vector<double> xyz;
  xyz.reserve(3 * points.size());
  for (const auto& p : points) xyz.insert(xyz.end(), {p.x(), p.y(), 0.0});
  std::vector<int> offsets(nt);
  for (int t = 0; t < nt; ++t) offsets[t] = nodes_per_cell * (t + 1);
  const std::vector<std::uint8_t> types(nt, static_cast<std::uint8_t>(vtk_type));

  // Element order of the VTK XML format: PointData, CellData, Points, Cells.
  std::string xml =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
      "byte_order=\"LittleEndian\" header_type=\"UInt64\"";
  if (format == VtuFormat::zlib) xml += " compressor=\"vtkZLibDataCompressor\"";
  xml += ">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(nv) +
         "\" NumberOfCells=\"" + std::to_string(nt) + "\">\n";
  std::string appended;
  auto add = [&](const DataArray& a) {
    describe(xml, a, format, appended.size());
    if (format != VtuFormat::ascii) append_block(appended, a.bytes, format);
  };
  for (bool cells : {false, true}) {
    xml += cells ? "<CellData>\n" : "<PointData>\n";
    for (const auto& f : fields)
      if (f.on_cells == cells) add(array_of("Float64", f.name, f.components, f.values, format));
    xml += cells ? "</CellData>\n" : "</PointData>\n";
  }
  xml += "<Points>\n";
  add(array_of("Float64", "", 3, xyz, format));
  xml += "</Points>\n<Cells>\n";
  add(array_of("Int32", "connectivity", nodes_per_cell, connectivity, format));
  add(array_of("Int32", "offsets", 1, offsets, format));
  add(array_of("UInt8", "types", 1, types, format));
  xml += "</Cells>\n</Piece>\n</UnstructuredGrid>\n";
  if (format != VtuFormat::ascii)
    xml += "<AppendedData encoding=\"raw\">\n_" + appended + "\n</AppendedData>\n";
  xml += "</VTKFile>\n";
  write_file_atomically(path, xml);
}

}  // namespace

void write_vtu(const std::string& path, const Mesh& mesh, const std::vector<VtuField>& fields,
               VtuFormat format) {
  std::vector<int> connectivity;
  connectivity.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) connectivity.insert(connectivity.end(), t.begin(), t.end());
  write_piece(path, mesh.vertices, connectivity, 3, 5, fields, format);  // VTK_TRIANGLE
}

void write_quadratic_vtu(const std::string& path, const std::vector<Point>& nodes,
                         const std::vector<std::array<int, 6>>& cells,
                         const std::vector<VtuField>& fields, VtuFormat format) {
  std::vector<int> connectivity;
  connectivity.reserve(6 * cells.size());
  for (const auto& t : cells) connectivity.insert(connectivity.end(), t.begin(), t.end());
  write_piece(path, nodes, connectivity, 6, 22, fields, format);  // VTK_QUADRATIC_TRIANGLE
}

void write_pvd(const std::string& path, const std::vector<PvdEntry>& entries) {
  write_atomically(path, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
    for (const auto& e : entries)
      out << "  <DataSet timestep=\"" << shortest(e.time) << "\" part=\"" << e.part << "\" file=\"" << e.file << "\"/>\n";
    out << "</Collection>\n</VTKFile>\n";
  });
}

}  // namespace fsi
