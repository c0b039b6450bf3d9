#pragma once
// The clearance watch's broad phase (docs/theory.md, "The broad phase and the Verlet list"): the
// pairs of axis-aligned boxes closer than a pruning distance, by sort and sweep along the axis
// on which the boxes' centres spread most. The pruning distance may fall during the sweep (the
// visit returns it anew), as the watch's threshold does; a pair is visited when its boxes'
// distance is below the pruning distance at that moment, so no pair closer than the last one
// returned is missed.
//
// Why not FCL's dynamic AABB tree (libfcl-dev, as before): it must be built anew at each broad
// phase (a refitted tree's topology is spoiled by a deployment's motion), from capsules placed
// by a transform and a quaternion each; the sort and sweep costs a sixth of that at 10² free
// capsules, a quarter at 10³ and two thirds at 10⁴ (docs/performance.md, "Clearance"). In a
// dense 3D cloud a sweep along one axis meets ~N^(2/3) boxes per box, so beyond about 10⁴ such
// members the tree would win again; deployable structures are long, and their sweep short.

#include <Eigen/Core>
#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace deploydyn {

struct AxisBox {
  Eigen::Vector3d low_m, high_m;
};

class BoxSweep {
 public:
  // visit(i, j) for each pair of `boxes` (indices, i ≠ j, each pair once) whose distance is below
  // `pruning_m`; visit returns the pruning distance from then on (m).
  template <class Visit>
  void pairs(const std::vector<AxisBox>& boxes, double pruning_m, Visit&& visit) {
    if (boxes.size() < 2) return;
    int axis = 0;
    Eigen::Vector3d low = boxes[0].low_m + boxes[0].high_m, high = low;
    for (const AxisBox& b : boxes) {
      low = low.cwiseMin(b.low_m + b.high_m);
      high = high.cwiseMax(b.low_m + b.high_m);
    }
    (high - low).maxCoeff(&axis);
    order_.resize(boxes.size());
    std::iota(order_.begin(), order_.end(), 0);
    std::sort(order_.begin(), order_.end(), [&](int a, int b) {
      return boxes[static_cast<std::size_t>(a)].low_m[axis] < boxes[static_cast<std::size_t>(b)].low_m[axis];
    });
    for (std::size_t k = 0; k < order_.size(); ++k) {
      const AxisBox& a = boxes[static_cast<std::size_t>(order_[k])];
      for (std::size_t l = k + 1; l < order_.size(); ++l) {
        const AxisBox& b = boxes[static_cast<std::size_t>(order_[l])];
        // Later boxes start farther along the axis: none of them is nearer than this one's gap.
        if (b.low_m[axis] - a.high_m[axis] >= pruning_m) break;
        const Eigen::Vector3d gap = (b.low_m - a.high_m).cwiseMax(a.low_m - b.high_m).cwiseMax(0.0);
        if (gap.squaredNorm() < pruning_m * pruning_m) pruning_m = visit(order_[k], order_[l]);
      }
    }
  }

 private:
  std::vector<int> order_;  // the boxes by their lower end along the sweep axis
};

}  // namespace deploydyn
