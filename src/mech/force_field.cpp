#include "mech/force_field.hpp"

#include <chrono>

namespace cortex {

double ForceField::value(const Eigen::VectorXd& x) { return evaluateTerms(all_, x, nullptr); }

double ForceField::valueAndGradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) {
  return evaluateTerms(all_, x, &gradient);
}

double ForceField::evaluateTerms(const std::vector<EnergyTerm*>& terms, const Eigen::VectorXd& x,
                                 Eigen::VectorXd* gradient) {
  const auto start = std::chrono::steady_clock::now();
  ++(gradient ? force_evaluations_ : energy_evaluations_);
  if (gradient) gradient->setZero(x.size());
  const Evaluation e{x.data(), gradient ? gradient->data() : nullptr, ++version_};
  double total = 0.0;
  for (EnergyTerm* term : terms) total += term->evaluate(e);
  if (gradient) {
    for (std::size_t i = 0; i < frozen_.size(); ++i)
      if (frozen_[i]) (*gradient)[static_cast<Eigen::Index>(i)] = 0.0;
    force_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return total;
}

std::vector<EnergyTerm*> ForceField::termsOf(const std::string& body) const {
  std::vector<EnergyTerm*> out;
  for (EnergyTerm* t : all_)
    if (t->actsOn(body)) out.push_back(t);
  return out;
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
