#include "io/vtu.hpp"

#include <iomanip>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace fsi {

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

// One piece: the points, `nodes_per_cell` point indices a cell (flat), its VTK type.
void write_piece(const std::string& path, const std::vector<Point>& points, const std::vector<int>& connectivity,
                 int nodes_per_cell, int vtk_type, const std::vector<VtuField>& fields) {
  const int nv = static_cast<int>(points.size());
  const int nt = static_cast<int>(connectivity.size()) / nodes_per_cell;
  for (const auto& f : fields)
    if (f.values.size() != static_cast<std::size_t>((f.on_cells ? nt : nv) * f.components))
      throw std::logic_error("vtu field '" + f.name + "' has the wrong size");
  write_atomically(path, [&](std::ostream& out) {
    out << std::setprecision(17);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
        << "<Piece NumberOfPoints=\"" << nv << "\" NumberOfCells=\"" << nt << "\">\n";
    // Element order of the VTK XML format: PointData, CellData, Points, Cells.
    for (bool cells : {false, true}) {
      out << (cells ? "<CellData>\n" : "<PointData>\n");
      for (const auto& f : fields) {
        if (f.on_cells != cells) continue;
        out << "<DataArray type=\"Float64\" Name=\"" << f.name << "\" NumberOfComponents=\""
            << f.components << "\" format=\"ascii\">\n";
        for (std::size_t i = 0; i < f.values.size(); ++i)
          out << f.values[i] << ((i + 1) % f.components == 0 ? '\n' : ' ');
        out << "</DataArray>\n";
      }
      out << (cells ? "</CellData>\n" : "</PointData>\n");
    }
    out << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& p : points) out << p.x() << ' ' << p.y() << " 0\n";
    out << "</DataArray>\n</Points>\n<Cells>\n"
        << "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < connectivity.size(); ++i)
      out << connectivity[i] << ((i + 1) % nodes_per_cell == 0 ? '\n' : ' ');
    out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
    for (int t = 1; t <= nt; ++t) out << nodes_per_cell * t << '\n';
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (int t = 0; t < nt; ++t) out << vtk_type << '\n';
    out << "</DataArray>\n</Cells>\n";
    out << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  });
}

}  // namespace

void write_vtu(const std::string& path, const Mesh& mesh, const std::vector<VtuField>& fields) {
  std::vector<int> connectivity;
  connectivity.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) connectivity.insert(connectivity.end(), t.begin(), t.end());
  write_piece(path, mesh.vertices, connectivity, 3, 5, fields);  // VTK_TRIANGLE
}

void write_quadratic_vtu(const std::string& path, const std::vector<Point>& nodes,
                         const std::vector<std::array<int, 6>>& cells, const std::vector<VtuField>& fields) {
  std::vector<int> connectivity;
  connectivity.reserve(6 * cells.size());
  for (const auto& t : cells) connectivity.insert(connectivity.end(), t.begin(), t.end());
  write_piece(path, nodes, connectivity, 6, 22, fields);  // VTK_QUADRATIC_TRIANGLE
}

void write_pvd(const std::string& path, const std::vector<PvdEntry>& entries) {
  write_atomically(path, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
    for (const auto& e : entries)
      out << "  <DataSet timestep=\"0\" part=\"" << e.part << "\" file=\"" << e.file << "\"/>\n";
    out << "</Collection>\n</VTKFile>\n";
  });
}

}  // namespace fsi
