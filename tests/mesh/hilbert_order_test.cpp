// mesh/hilbert_order: the curve visits every cell of a grid once, each step to a
// neighbouring cell; the first half of the points covers one half of the square; ties
// keep their order; a flat or empty set of points is ordered too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <vector>

#include "mesh/hilbert_order.hpp"

namespace fsi::hilbert_order_test {
namespace {

// The centres of a 64 × 64 grid of unit cells, given in a shuffled order.
std::vector<Point> grid(int cells) {
  std::vector<Point> points;
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) points.emplace_back(((i * 37) % cells) + 0.5, ((j * 11) % cells) + 0.5);
  return points;
}

TEST(HilbertOrder, OnAGridEveryStepGoesToANeighbour) {
  const std::vector<Point> points = grid(64);
  const std::vector<int> order = hilbert_order(points);
  ASSERT_EQ(order.size(), points.size());
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 0; k < sorted.size(); ++k) ASSERT_EQ(sorted[k], static_cast<int>(k));  // a permutation
  for (std::size_t k = 0; k + 1 < order.size(); ++k) {
    const Point step = points[static_cast<std::size_t>(order[k + 1])] - points[static_cast<std::size_t>(order[k])];
    ASSERT_NEAR(step.cwiseAbs().sum(), 1.0, 1e-12) << "step " << k;
  }
}

TEST(HilbertOrder, TheFirstHalfIsAHalfOfTheSquare) {
  const std::vector<Point> points = grid(64);
  const std::vector<int> order = hilbert_order(points);
  // The curve starts at the origin's corner and leaves its first half (the lower half,
  // or the left one) for the second: the first half lies on one side of a mid-line.
  int below = 0, left = 0;
  for (std::size_t k = 0; k < order.size() / 2; ++k) {
    below += points[static_cast<std::size_t>(order[k])].y() < 32;
    left += points[static_cast<std::size_t>(order[k])].x() < 32;
  }
  EXPECT_EQ(std::max(below, left), static_cast<int>(order.size() / 2));
}

TEST(HilbertOrder, TiesKeepTheirOrderAndAFlatBoxIsOrdered) {
  const std::vector<Point> same(5, Point(1.0, 2.0));
  std::vector<int> identity(5);
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_EQ(hilbert_order(same), identity);
  // Points on a line (a flat box) are ordered: these four as along the line.
  const std::vector<Point> line = {Point(3, 0), Point(1, 0), Point(2, 0), Point(0, 0)};
  EXPECT_EQ(hilbert_order(line), (std::vector<int>{3, 1, 2, 0}));
  EXPECT_TRUE(hilbert_order({}).empty());
}

TEST(HilbertOrder, TheIndexOfTheFirstCells) {
  // The 2 × 2 curve: (0,0), (0,1), (1,1), (1,0).
  EXPECT_EQ(hilbert_index(0, 0, 1), 0u);
  EXPECT_EQ(hilbert_index(0, 1, 1), 1u);
  EXPECT_EQ(hilbert_index(1, 1, 1), 2u);
  EXPECT_EQ(hilbert_index(1, 0, 1), 3u);
}

}  // namespace
}  // namespace fsi::hilbert_order_test
