// The total energy: a list of terms, summed, with frozen coordinates masked out.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "mech/energy_term.hpp"
#include "mech/objective.hpp"

namespace cortex {

struct TermEnergy {
  std::string owner, name;
  double energy;
};

class ForceField final : public Objective {
 public:
  // Returns the term, which stays owned by the force field.
  template <class Term>
  Term& add(std::unique_ptr<Term> term) {
    Term& t = *term;
    terms_.push_back(std::move(term));
    return t;
  }
  // Coordinates whose mask entry is non-zero never move (their gradient reads zero).
  void setFrozen(std::vector<char> frozen) { frozen_ = std::move(frozen); }
  void setTime(double t) {
    for (auto& term : terms_) term->setTime(t);
  }

  double value(const Eigen::VectorXd& x) override;
  double valueAndGradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) override;
  std::vector<TermEnergy> breakdown(const Eigen::VectorXd& x);
  // -dE/dx of the contact terms alone (EnergyTerm::isContact), frozen coordinates
  // included: the forces walls and other bodies put on each point. Not counted as a
  // force evaluation (it is feedback, not minimization).
  Eigen::VectorXd contactForces(const Eigen::VectorXd& x);

  std::int64_t forceEvaluations() const { return force_evaluations_; }
  std::int64_t energyEvaluations() const { return energy_evaluations_; }
  void restoreCounters(std::int64_t force, std::int64_t energy) {
    force_evaluations_ = force;
    energy_evaluations_ = energy;
  }

 private:
  std::vector<std::unique_ptr<EnergyTerm>> terms_;
  std::vector<char> frozen_;
  std::uint64_t version_ = 0;
  std::int64_t force_evaluations_ = 0, energy_evaluations_ = 0;
};

}  // namespace cortex
