#include "run/case_contact.hpp"

#include <memory>
#include <vector>

#include "solid/signed_distance.hpp"

namespace fsi {
namespace {

std::unique_ptr<Obstacle> make_obstacle(const ObstacleSpec& o, double diam) {
  if (o.shape == "disk") return std::make_unique<DiskObstacle>(Point(o.x0, o.y0), o.r);
  if (o.shape == "polygon") return std::make_unique<PolygonObstacle>(o.points, kPolygonMargin * diam);
  return std::make_unique<HalfPlaneObstacle>(o.point, o.normal);
}

}  // namespace

ContactGap case_contact_gap(const Case& c, const Mesh& mesh) {
  std::vector<std::unique_ptr<Obstacle>> obstacles;
  if (c.obstacles_given) {
    for (const ObstacleSpec& o : c.obstacles) obstacles.push_back(make_obstacle(o, diameter(mesh)));
  } else {
    obstacles.push_back(std::make_unique<DiskObstacle>(Point(c.obstacle.x0, c.obstacle.y0), c.obstacle.r));
  }
  return ContactGap(std::move(obstacles), c.contact.gap == "normal", mesh, c.contact.boundary);
}

}  // namespace fsi
