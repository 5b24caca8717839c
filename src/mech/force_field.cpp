#include "mech/force_field.hpp"

namespace cortex {

double ForceField::value(const Eigen::VectorXd& x) {
  ++energy_evaluations_;
  const Evaluation e{x.data(), nullptr, ++version_};
  double total = 0.0;
  for (auto& term : terms_) total += term->evaluate(e);
  return total;
}

double ForceField::valueAndGradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) {
  ++force_evaluations_;
  gradient.setZero(x.size());
  const Evaluation e{x.data(), gradient.data(), ++version_};
  double total = 0.0;
  for (auto& term : terms_) total += term->evaluate(e);
  for (std::size_t i = 0; i < frozen_.size(); ++i)
    if (frozen_[i]) gradient[static_cast<Eigen::Index>(i)] = 0.0;
  return total;
}

std::vector<TermEnergy> ForceField::breakdown(const Eigen::VectorXd& x) {
  const Evaluation e{x.data(), nullptr, ++version_};
  std::vector<TermEnergy> out;
  for (auto& term : terms_) out.push_back({term->owner(), term->name(), term->evaluate(e)});
  return out;
}

Eigen::VectorXd ForceField::contactForces(const Eigen::VectorXd& x) {
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(x.size());
  const Evaluation e{x.data(), gradient.data(), ++version_};
  for (auto& term : terms_)
    if (term->isContact()) term->evaluate(e);
  return -gradient;
}

}  // namespace cortex
