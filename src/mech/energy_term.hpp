// One physical energy term: the only thing a new force has to implement.
#pragma once

#include <cstdint>
#include <string>

namespace cortex {

class Body;

// Coordinates of every degree of freedom, and where to add the gradient (may be null
// when only the energy is wanted). `version` changes whenever x changes, so terms that
// share derived geometry can cache it. When `alone` is set, x and the gradient hold that
// body's points only, laid out from offset zero (a membrane's shape relaxation, the
// filaments' relaxation under "auto"), and every other body stays at its stored
// positions: terms between bodies read those from the body and give them no gradient.
// `held`, when not zero, names the bodies' stored positions: evaluations with the same
// number promise that none of them changed in between (one relaxation of a body alone,
// which writes its result back only when it is done), so a term may keep what it read of
// them instead of reading them again. Zero promises nothing.
struct Evaluation {
  const double* x = nullptr;
  double* gradient = nullptr;
  std::uint64_t version = 0;
  const Body* alone = nullptr;
  std::uint64_t held = 0;
  // Whether `body`'s points are in x (and get gradient): every body's unless one is alone.
  bool moves(const Body& body) const { return !alone || alone == &body; }
};

class EnergyTerm {
 public:
  virtual ~EnergyTerm() = default;
  // Name of the physical term ("bending", "area", ...) and of the object it acts on
  // (a membrane's name); summary.json groups energies by both.
  virtual const std::string& name() const = 0;
  virtual const std::string& owner() const = 0;
  // Whether it acts on the body of this name: its owner, and for a term between bodies
  // (membrane–filament excluded volume) the others too. A body relaxed on its own is
  // relaxed under every term that acts on it.
  virtual bool actsOn(const std::string& body) const { return body == owner(); }
  // Returns the energy (pN·nm) and, if e.gradient is set, adds dE/dx (pN) to it.
  virtual double evaluate(const Evaluation& e) = 0;
  // Evaluates the term's scheduled parameters at time t (s).
  virtual void setTime(double /*t*/) {}
  // A contact term (walls, excluded volume between bodies): its forces on a filament's
  // end are the load of the Brownian ratchet (thesis eq. 2.14), which the mechanochemical
  // feedback reads from exactly these terms.
  virtual bool isContact() const { return false; }
};

}  // namespace cortex
