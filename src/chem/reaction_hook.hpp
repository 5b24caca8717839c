// Reactions whose effect reaches beyond copy numbers: a filament end that grows, a linker
// that binds two particular filaments. The engine treats them as ordinary mass-action
// channels (rate factor per compartment = how many such sites the compartment holds,
// each weighted by its force-dependent factor) and, when one fires, asks the hook to
// carry it out on the object it picks. The hook may refuse (the picked site turned out
// to be occupied or gone): the event is then void and no copies change, which is exact
// thinning of a propensity that counted too many sites. Inside fired() the hook may call
// setCopies and setRateFactor on the engine for any compartment: the engine keeps its
// pending times consistent (Gibson & Bruck 2000).
#pragma once

#include "core/random.hpp"
#include "core/types.hpp"

namespace cortex {

class ChemistryEngine;

class ReactionHook {
 public:
  virtual ~ReactionHook() = default;
  // Reaction `reaction` (marked hooked in the model) fires in `compartment`. Returns
  // whether it happened; the engine applies the reaction's copy changes only then.
  // `random` is the engine's own stream, so hooked runs stay a function of the seed.
  virtual bool fired(Index reaction, Index compartment, ChemistryEngine& engine, RandomStream& random) = 0;
};

}  // namespace cortex
