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

void write_vtu(const std::string& path, const Mesh& mesh, const std::vector<VtuField>& fields) {
  const int nv = mesh.num_vertices(), nt = mesh.num_triangles();
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
    for (const auto& p : mesh.vertices) out << p.x() << ' ' << p.y() << " 0\n";
    out << "</DataArray>\n</Points>\n<Cells>\n"
        << "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto& t : mesh.triangles) out << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
    for (int t = 1; t <= nt; ++t) out << 3 * t << '\n';
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (int t = 0; t < nt; ++t) out << "5\n";  // VTK_TRIANGLE
    out << "</DataArray>\n</Cells>\n";
    out << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  });
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
