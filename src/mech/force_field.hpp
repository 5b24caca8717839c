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
    all_.push_back(&t);
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
  // The same for some of the terms (in their order here), counted as evaluations of the
  // field: relaxing some bodies while the terms of the others are left out.
  double evaluateTerms(const std::vector<EnergyTerm*>& terms, const Eigen::VectorXd& x, Eigen::VectorXd* gradient);
  // The terms acting on one body (EnergyTerm::actsOn), in order.
  std::vector<EnergyTerm*> termsOf(const std::string& body) const;
  // Those terms as an Objective over one body's own coordinates (Evaluation::alone): x
  // holds its points only, and the other bodies stay where they are held, so a term
  // between this body and another does not move the other. The body must sit at offset
  // zero while this is evaluated (its terms read it there, BodyAtOffsetZero); `first` is
  // where its coordinates start in the whole vector, for the frozen mask. The minimizer's
  // vectors are then the body's size, not the system's: a filament network's relaxation
  // beside a 3.5k-vertex membrane did ten times the vector work of its forces.
  class Alone final : public Objective {
   public:
    // The bodies' stored positions must not change while it is evaluated (Evaluation::held).
    Alone(ForceField& field, std::vector<EnergyTerm*> terms, const Body& body, Eigen::Index first)
        : field_(field), terms_(std::move(terms)), body_(body), first_(first), held_(field.newVersion()) {}
    double value(const Eigen::VectorXd& x) override {
      return field_.evaluate(terms_, x, nullptr, &body_, first_, held_);
    }
    double valueAndGradient(const Eigen::VectorXd& x, Eigen::VectorXd& g) override {
      return field_.evaluate(terms_, x, &g, &body_, first_, held_);
    }

   private:
    ForceField& field_;
    std::vector<EnergyTerm*> terms_;
    const Body& body_;
    Eigen::Index first_;
    std::uint64_t held_;
  };
  // A version no evaluation has used yet, for callers that evaluate terms themselves (the
  // membrane relaxation): terms cache derived geometry by version.
  std::uint64_t newVersion() { return ++version_; }
  // Evaluations done (and timed) by such callers.
  void countForceEvaluations(std::int64_t n, double seconds) {
    force_evaluations_ += n;
    force_seconds_ += seconds;
  }
  std::vector<TermEnergy> breakdown(const Eigen::VectorXd& x);
  // -dE/dx of the contact terms alone (EnergyTerm::isContact), frozen coordinates
  // included: the forces walls and other bodies put on each point. Not counted as a
  // force evaluation (it is feedback, not minimization).
  Eigen::VectorXd contactForces(const Eigen::VectorXd& x);

  std::int64_t forceEvaluations() const { return force_evaluations_; }
  // Wall time spent in force evaluations by this process (not checkpointed: a clock).
  double forceSeconds() const { return force_seconds_; }
  std::int64_t energyEvaluations() const { return energy_evaluations_; }
  void restoreCounters(std::int64_t force, std::int64_t energy) {
    force_evaluations_ = force;
    energy_evaluations_ = energy;
  }

 private:
  // Terms at x (every body's coordinates, or `alone`'s from offset zero, whose first
  // coordinate is `first` in the whole vector's frozen mask; `held`: Evaluation::held).
  double evaluate(const std::vector<EnergyTerm*>& terms, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                  const Body* alone, Eigen::Index first, std::uint64_t held = 0);

  std::vector<std::unique_ptr<EnergyTerm>> terms_;
  std::vector<EnergyTerm*> all_;  // the same, for evaluateTerms
  std::vector<char> frozen_;
  std::uint64_t version_ = 0;
  std::int64_t force_evaluations_ = 0, energy_evaluations_ = 0;
  double force_seconds_ = 0.0;
};

}  // namespace cortex
