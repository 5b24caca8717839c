#include "mech/force_field.hpp"

#include <algorithm>
#include <chrono>

namespace cortex {

double ForceField::value(const Eigen::VectorXd& x) { return evaluate(all_, x, nullptr, nullptr, 0); }

double ForceField::valueAndGradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) {
  return evaluate(all_, x, &gradient, nullptr, 0);
}

double ForceField::evaluateTerms(const std::vector<EnergyTerm*>& terms, const Eigen::VectorXd& x,
                                 Eigen::VectorXd* gradient) {
  return evaluate(terms, x, gradient, nullptr, 0);
}

double ForceField::evaluate(const std::vector<EnergyTerm*>& terms, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                            const Body* alone, Eigen::Index first, std::uint64_t held) {
  const auto start = std::chrono::steady_clock::now();
  ++(gradient ? force_evaluations_ : energy_evaluations_);
  if (gradient) gradient->setZero(x.size());
  const Evaluation e{x.data(), gradient ? gradient->data() : nullptr, ++version_, alone, held};
  double total = 0.0;
  for (EnergyTerm* term : terms) total += term->evaluate(e);
  if (gradient) {
    const Eigen::Index end = std::min<Eigen::Index>(x.size(), static_cast<Eigen::Index>(frozen_.size()) - first);
    for (Eigen::Index i = 0; i < end; ++i)
      if (frozen_[static_cast<std::size_t>(first + i)]) (*gradient)[i] = 0.0;
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
