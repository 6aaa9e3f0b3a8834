#include "mesh/constrained_delaunay.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <exception>
#include <string>
#include <utility>

#include "mesh/mesh_error.hpp"

namespace fsi {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// A vertex's info: its input index, −1 for the refinement's points (CGAL default-
// constructs the info of the vertices it adds: a plain int would be left undefined).
struct VertexIndex {
  int index = -1;
};
using VertexBase = CGAL::Delaunay_mesh_vertex_base_2<
    Kernel, CGAL::Triangulation_vertex_base_with_info_2<VertexIndex, Kernel>>;
// The face's info: its nesting level (how many loops enclose it), −1 before marking.
using FaceBase = CGAL::Delaunay_mesh_face_base_2<
    Kernel, CGAL::Constrained_Delaunay_triangulation_face_base_2<
                Kernel, CGAL::Constrained_triangulation_face_base_2<
                            Kernel, CGAL::Triangulation_face_base_with_info_2<int, Kernel>>>>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<
    Kernel, CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>, CGAL::Exact_predicates_tag>;
using CgalPoint = Kernel::Point_2;

// CGAL's size criteria with a size that varies: a triangle is refined first if its
// longest edge exceeds factor · h(x) at its centroid, then if sin² of its smallest angle
// is under 0.125 (20.7°, the bound for which Delaunay refinement is proved to end).
class SizeFieldCriteria {
 public:
  using Face_handle = Cdt::Face_handle;
  using Quality = CGAL::Delaunay_mesh_size_criteria_2<Cdt>::Quality;
  static constexpr double kSineSquaredBound = 0.125;

  SizeFieldCriteria(const SizeField* size, double factor) : size_(size), factor_(factor) {}

  class Is_bad {
   public:
    Is_bad(const SizeField* size, double factor) : size_(size), factor_(factor) {}
    CGAL::Mesh_2::Face_badness operator()(const Quality q) const {
      if (q.size() > 1) return CGAL::Mesh_2::IMPERATIVELY_BAD;
      return q.sine() < kSineSquaredBound ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }
    CGAL::Mesh_2::Face_badness operator()(const Face_handle& f, Quality& q) const {
      const CgalPoint &a = f->vertex(0)->point(), &b = f->vertex(1)->point(),
                      &c = f->vertex(2)->point();
      const double ab = CGAL::squared_distance(a, b), bc = CGAL::squared_distance(b, c),
                   ca = CGAL::squared_distance(c, a);
      const double longest = std::max({ab, bc, ca}), shortest = std::min({ab, bc, ca});
      const double middle = ab + bc + ca - longest - shortest;
      const Point centroid((a.x() + b.x() + c.x()) / 3, (a.y() + b.y() + c.y()) / 3);
      const double bound = factor_ * (*size_)(centroid);
      q.second = longest / (bound * bound);
      const double twice_area =
          (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
      q.first = q.size() > 1 ? 1 : twice_area * twice_area / (longest * middle);
      return operator()(q);
    }

   private:
    const SizeField* size_;
    double factor_;
  };
  Is_bad is_bad_object() const { return Is_bad(size_, factor_); }

 private:
  const SizeField* size_;
  double factor_;
};

// Each face's nesting level: 0 outside every loop, +1 across each constrained edge.
// Faces at an odd level are the domain.
void mark_domain(Cdt& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::vector<Cdt::Face_handle> level_seeds = {cdt.infinite_face()}, next_level;
  for (int level = 0; !level_seeds.empty(); ++level) {
    std::vector<Cdt::Face_handle> stack;
    for (const auto& f : level_seeds)
      if (f->info() < 0) f->info() = level, stack.push_back(f);
    next_level.clear();
    while (!stack.empty()) {
      const Cdt::Face_handle f = stack.back();
      stack.pop_back();
      f->set_in_domain(level % 2 == 1);
      for (int i = 0; i < 3; ++i) {
        const Cdt::Face_handle g = f->neighbor(i);
        if (g->info() >= 0) continue;
        if (cdt.is_constrained({f, i})) {
          next_level.push_back(g);
        } else {
          g->info() = level;
          stack.push_back(g);
        }
      }
    }
    std::swap(level_seeds, next_level);
  }
}

void insert(Cdt& cdt, const DelaunayInput& in) {
  const int nb = static_cast<int>(in.boundary.size());
  std::vector<std::pair<CgalPoint, VertexIndex>> points;
  points.reserve(in.boundary.size() + in.interior.size());
  for (int i = 0; i < nb; ++i)
    points.emplace_back(CgalPoint(in.boundary[i].x(), in.boundary[i].y()), VertexIndex{i});
  for (std::size_t i = 0; i < in.interior.size(); ++i)
    points.emplace_back(CgalPoint(in.interior[i].x(), in.interior[i].y()),
                        VertexIndex{nb + static_cast<int>(i)});
  cdt.insert(points.begin(), points.end());  // spatially sorted inside
  std::vector<Cdt::Vertex_handle> boundary(nb);
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (v->info().index < nb) boundary[v->info().index] = v;
  if (static_cast<int>(cdt.number_of_vertices()) != nb + static_cast<int>(in.interior.size()))
    throw MeshError("two of the points to triangulate coincide");
  for (const auto& [p, q] : in.segments) cdt.insert_constraint(boundary[p], boundary[q]);
  if (static_cast<int>(cdt.number_of_vertices()) != nb + static_cast<int>(in.interior.size()))
    throw MeshError("the boundary crosses itself");
}

DelaunayMesh extract(Cdt& cdt, int input_points) {
  DelaunayMesh out;
  // Numbering: the input points keep theirs, the refinement's follow.
  std::vector<Cdt::Vertex_handle> by_index(input_points);
  std::vector<Cdt::Vertex_handle> added;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if (v->info().index >= 0)
      by_index[v->info().index] = v;
    else
      added.push_back(v);
  }
  for (auto& v : added) by_index.push_back(v);
  for (int i = 0; i < static_cast<int>(by_index.size()); ++i)
    by_index[i]->info().index = i;  // the output's
  for (const auto& v : by_index) out.vertices.emplace_back(v->point().x(), v->point().y());
  // Each constrained edge once: from its face in the domain (the other is outside).
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    out.triangles.push_back(
        {f->vertex(0)->info().index, f->vertex(1)->info().index, f->vertex(2)->info().index});
    for (int i = 0; i < 3; ++i)
      if (f->is_constrained(i))
        out.boundary_edges.push_back(
            {f->vertex(Cdt::ccw(i))->info().index, f->vertex(Cdt::cw(i))->info().index});
  }
  return out;
}

}  // namespace

DelaunayMesh constrained_delaunay(const DelaunayInput& input, const SizeField& size,
                                  double max_edge_over_size) {
  try {
    Cdt cdt;
    insert(cdt, input);
    mark_domain(cdt);
    CGAL::Delaunay_mesher_2<Cdt, SizeFieldCriteria> mesher(
        cdt, SizeFieldCriteria(&size, max_edge_over_size));
    mesher.init(/*domain_specified=*/true);
    // Point by point, counted: a feature far below h(x) (a 0.06 × 1e-12 strip) would
    // have it add points without end.
    const std::size_t inputs = input.boundary.size() + input.interior.size();
    const std::size_t limit = std::max<std::size_t>(100000, inputs);
    for (std::size_t added = 0; mesher.step_by_step_refine_mesh();)
      if (++added > limit)
        throw MeshError(
            "Delaunay refinement added over " + std::to_string(limit) +
            " points without ending: the domain has a side or a gap far thinner than the mesh "
            "size h");
    return extract(cdt, static_cast<int>(inputs));
  } catch (const MeshError&) {
    throw;
  } catch (const std::exception& e) {  // CGAL's precondition and assertion failures
    throw MeshError(std::string("the constrained Delaunay triangulation failed: ") + e.what());
  }
}

}  // namespace fsi
