// What a minimizer minimizes: a scalar function of all coordinates with its gradient.
#pragma once

#include <Eigen/Core>

namespace cortex {

class Objective {
 public:
  virtual ~Objective() = default;
  virtual double value(const Eigen::VectorXd& x) = 0;
  // Overwrites `gradient` with dE/dx.
  virtual double valueAndGradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) = 0;
};

}  // namespace cortex
