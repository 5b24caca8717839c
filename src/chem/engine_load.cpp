// The engines' events limit (EngineBase::checkLoad): the load by channel and the message
// that names the largest one, apart from the event loop itself.
#include <fmt/format.h>

#include "chem/engine_base.hpp"
#include "core/error.hpp"

namespace cortex {

ChemistryEngine::Load EngineBase::load() const {
  Load out;
  auto note = [&](double value, const std::string& what, const char* cause) {
    out.total += value;
    if (!(value <= out.largest)) out.largest = value, out.largest_channel = what, out.largest_cause = cause;
  };
  for (Index s = 0; s < S_; ++s) {
    double hops = 0.0;
    for (Index i = region_start_[net_.speciesRegion[s]]; i < region_start_[net_.speciesRegion[s] + 1]; ++i)
      hops += (weighted(s) ? hopOut(i, s) : degree(i) * hop_rate_[s]) * copies_[static_cast<std::size_t>(i) * S_ + s];
    // The hop rates already carry the drift of a membrane species' energies, which can
    // outgrow the diffusion constant by far (a pair interaction's range past the mesh).
    const bool biased = !drift_[s].empty() || interacting(s);
    note(hops, "diffusion of \"" + species_[s].name + "\"",
         biased ? "check its diffusion constant and the potential, interaction or curvature energy that drives its "
                  "hops (their height and range)"
                : "check its diffusion constant");
  }
  for (Index r = 0; r < R_; ++r) {
    double sum = 0.0;
    for (Index i = 0; i < N_; ++i)
      sum += factor_[static_cast<std::size_t>(i) * R_ + r] * constantAt(i, r) * confinementScale(i, r) *
             combinations(net_.kernels[r], &copies_[static_cast<std::size_t>(i) * S_],
                          &copies_[static_cast<std::size_t>(holder_[i]) * S_]);
    note(sum, "reaction \"" + equations_[r] + "\"", "check its rate");
  }
  return out;
}

void EngineBase::checkLoad(double total, double dt, std::int64_t drawn) const {
  if (drawn > 0 && interrupt_) interrupt_();
  const double expected = static_cast<double>(drawn) + total * dt;
  if (expected <= event_limit_) return;
  const Load l = load();
  std::string culprit = "the largest channel is " + l.largest_channel + " at " + fmt::format("{:.3g}", l.largest) +
                        " events/s: " + l.largest_cause;
  // The channels above are the plain rates; what a membrane species' energies multiply
  // them by (drift of hops, e^{V} of unbinding) is only in the engine's total.
  if (l.total < 0.5 * total)
    culprit = fmt::format("{:.3g} of the {:.3g} events/s come from rates that a membrane species' energies multiply "
                          "(its potential, pair interaction or curvature energy in hops and unbinding): check their "
                          "heights; of the plain rates, {}",
                          total - l.total, total, culprit);
  const std::string count =
      drawn == 0 ? fmt::format("about {:.3g} events expected in a window of {:g} s", expected, dt)
                 : fmt::format("{} events drawn in this window and about {:.3g} more expected in the {:.3g} s left of "
                               "it (a reaction network growing without bound?)",
                               drawn, total * dt, dt);
  throw RunError(fmt::format("chemistry: {}, over the limit of {:g} (chemistry.max_events_per_window); {}", count,
                             event_limit_, culprit));
}

}  // namespace cortex
