#include "solvers/mixed_control.hpp"

#include <Eigen/LU>

namespace mortar::harness {

Eigen::Vector3d solve_on_free(const PointTargets& t, const Eigen::Matrix3d& K, const Eigen::Vector3d& rhs,
                              int n_dir) {
  Eigen::Matrix3d K_FF = Eigen::Matrix3d::Identity();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (int i = 0; i < n_dir; ++i) {
    if (!free_component(t, i)) continue;
    b[i] = rhs[i];
    for (int j = 0; j < n_dir; ++j)
      if (free_component(t, j)) K_FF(i, j) = K(i, j);
  }
  return K_FF.fullPivLu().solve(b);
}

std::string failure_location(int point, int step, long increment) {
  return "point " + std::to_string(point + 1) + ", step " + std::to_string(step) + ", increment " +
         std::to_string(increment) + ": ";
}

}  // namespace mortar::harness
