// Filament reactions in the stochastic engine (MEDYAN's scheme; Popov, Komianos & Papoian
// 2016): end growth and shrinkage, nucleation, linker and motor binding, unbinding and
// walking, Arp2/3 branching and unbranching, each one hooked reaction per type. A hooked
// reaction's rate factor in a compartment is the sum over the sites it may act on there
// (ends, bound proteins, candidate site pairs), each weighted by its force-dependent
// factor; when it fires, fired() picks one of them with that weight and edits the
// network. After each minimization the mechanochemical feedback (sim/) hands it the
// forces the force field's contact terms put on every end and the tensions of the bound
// proteins (Binding::tension); update() turns them into rates (Brownian ratchet, thesis
// eq. 2.14; slip and catch bonds; motor stall) and finds the site pairs within binding
// range. It computes no force itself.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "chem/chemistry_engine.hpp"
#include "chem/reaction_hook.hpp"
#include "filament/binding_candidates.hpp"
#include "filament/end_load_probe.hpp"
#include "filament/filament_network.hpp"
#include "filament/walls.hpp"

namespace cortex {

enum class FilamentReaction : std::uint8_t {
  kPlusGrow, kPlusShrink, kMinusGrow, kMinusShrink, kNucleate,
  kLinkerBind, kLinkerUnbind, kMotorBind, kMotorUnbind, kMotorWalk,
  kBranch, kUnbranch,
};
inline constexpr int kFilamentReactionKinds = 12;

class FilamentChemistry final : public ReactionHook {
 public:
  // `grid`: the compartments (the engine's 3D subvolumes, in the same order); kT in
  // pN·nm. Checks that the species the config parser resolved exist among `species`
  // (InputError otherwise).
  FilamentChemistry(FilamentNetwork& network, const CompartmentGrid& grid, const std::vector<SpeciesDef>& species,
                    double kT);

  // Appends one reaction per (kind, type) with a non-zero rate to `model`, owned by
  // "filaments".
  void addReactions(ChemistryModel& model);
  // Takes over the engine's rate factors of those reactions and carries them out.
  void attach(ChemistryEngine& engine);

  bool fired(Index reaction, Index compartment, ChemistryEngine& engine, RandomStream& random) override;

  // After a minimization (or at the start, or after a restore): `end_forces[f]` is the
  // force (pN) the contact terms put on filament f's minus and plus end beads, and the
  // tensions of the bound linkers and motors are set. Recomputes the ratchet factors,
  // where each bound protein is, the candidate binding pairs and branching sites, then
  // every rate factor that changed.
  void update(const std::vector<std::array<Vec3, 2>>& end_forces);
  // Bodies that stand still between relaxations and act on ends (membranes, walls, other
  // filaments): their part of an end's load is weighed over its growth step where they
  // say how (EndLoadProbe::stepCorrection), and after each growth or shrinkage of an end
  // replaced by what they put on the end where it now is. Null: none.
  void setEndLoadProbe(const EndLoadProbe* probe) { probe_ = probe; }
  // Where the monomers of filament type `type` live, when a membrane confines them to one
  // of its sides (true on that side): nuclei of the type then form there, at points drawn
  // uniformly in the compartment's part on that side (the engine's propensity already
  // counts the monomers' concentration in that part). Unset: anywhere in the compartment.
  using Side = std::function<bool(const Vec3&)>;
  void setNucleationSide(Index type, Side side);
  // Whether a straight nucleus between two points would pass through a body no filament
  // crosses (a membrane): such a nucleus is a void event (thinning by the small share of
  // placements that straddle it), as one outside the boundary is. Unset: none.
  using Blocked = std::function<bool(const Vec3&, const Vec3&)>;
  void setNucleationBlocked(Blocked blocked) { nucleation_blocked_ = std::move(blocked); }

  // Ratchet factor of filament f's end (1 = unloaded) and the load behind it (pN).
  double ratchetFactor(Index f, bool plus_end) const { return ratchet_[f][plus_end ? 1 : 0]; }
  double endLoad(Index f, bool plus_end) const { return load_[f][plus_end ? 1 : 0]; }
  double maxEndLoad() const;  // pN, over every end

  // Force-dependent laws (exposed for tests).
  double slipFactor(const LinkerType& l, double tension) const;
  // `heads`: the motor's head count (0: not modelled, MotorType::heads_min).
  static double catchFactor(const MotorType& m, double tension, int heads = 0);
  static double walkFactor(const MotorType& m, double tension, int heads = 0);
  // N_b(F) of a motor with `heads` heads (> 0) under tension F.
  static double boundHeads(const MotorType& m, double tension, int heads);

 private:
  struct Channel {
    FilamentReaction kind;
    Index type;      // filament, linker, motor or brancher type
    Index reaction;  // index in the model
  };
  Index channelOf(FilamentReaction kind, Index type) const;
  Index compartmentOf(const Vec3& x) const { return grid_.locate(x); }
  void computeLoads(const std::vector<std::array<Vec3, 2>>& end_forces);
  // Load and ratchet factor of filament f's end under `force` (pN, Brownian ratchet).
  void loadEnd(Index f, bool plus_end, const Vec3& force);
  // One monomer along the growth direction of filament f's end.
  Vec3 growthStep(Index f, bool plus_end) const;
  // The ratchet of filament f's end after an event moved it (setEndLoadProbe).
  void reload(Index f, bool plus_end);
  // A filament just made (nucleus, branch): its ends loaded by the probe, then counted.
  void addNew(Index f);
  // Makes room for filament f's ratchet and load.
  void track(Index f);
  const Vec3& endBead(Index f, bool plus_end) const {
    const Filament& fil = net_.filaments()[f];
    return plus_end ? fil.beads.back() : fil.beads.front();
  }
  void locateBound();
  void findCandidates();
  // Rate factors: pending_ holds the sums of weights, updated by +-contributions as the
  // network changes inside a window; flush() passes the entries that changed to the
  // engine. rebuildFactors() recomputes all of them from scratch (after a minimization,
  // and after rare events that touch many things), which also clears rounding drift.
  void contribute(FilamentReaction kind, Index type, Index c, double w);
  void contributeEnds(Index f, double sign);
  static void file(std::vector<Index>& bucket, Index i, double sign);
  void contributeBinding(BinderKind kind, const Binding& b, double sign);
  void contributeBranch(const Branch& b, double sign);
  void rebuildFactors();
  void flush();
  // The event, on the object picked with its weight among those in compartment c.
  bool fireEnd(const Channel& ch, Index c, ChemistryEngine& engine, RandomStream& random);
  bool fireNucleation(const Channel& ch, Index c, RandomStream& random);
  bool fireBind(const Channel& ch, Index c, RandomStream& random);
  bool fireUnbind(const Channel& ch, Index c, RandomStream& random);
  bool fireWalk(const Channel& ch, Index c, RandomStream& random);
  bool fireBranch(const Channel& ch, Index c, RandomStream& random);
  bool fireUnbranch(const Channel& ch, Index c, RandomStream& random);
  void release(const std::vector<Release>& released, ChemistryEngine& engine);

  FilamentNetwork& net_;
  CompartmentGrid grid_;
  ReactionRange range_;  // its reactions in the model
  RateFactors factors_;  // and their rate factors in the engine (once attached)
  Walls walls_;  // where nuclei may form
  std::vector<Side> nucleation_side_;  // per filament type, empty if unconfined
  Blocked nucleation_blocked_;
  double kT_;
  std::vector<Index> monomer_species_;  // per filament type, -1 if none
  std::vector<Channel> channels_;
  std::array<std::vector<Index>, kFilamentReactionKinds> lookup_;  // [kind][type] -> channel or -1
  std::vector<double> factor_;                                       // [channel * C + c], as set in the engine
  std::vector<double> pending_;                                      // the same, as the network now is
  std::vector<std::size_t> dirty_;                                   // entries of pending_ changed since flush
  std::vector<char> is_dirty_;
  std::vector<BindingCandidates> candidates_;                              // per channel (binding kinds only)
  std::vector<std::array<double, 2>> ratchet_, load_;                // per filament: minus, plus
  const EndLoadProbe* probe_ = nullptr;
  // Per filament, minus and plus end, at the last relaxation: the contact force with the
  // probe's part weighed over the growth step, and that part.
  std::vector<std::array<Vec3, 2>> relaxed_force_, probe_force_;
  std::vector<std::array<Index, 2>> end_compartment_;                // per filament: minus, plus
  std::array<std::vector<std::vector<Index>>, 2> ends_in_;           // [minus/plus][c]: filaments, sorted
  std::vector<Release> released_;                                    // scratch
};

}  // namespace cortex
