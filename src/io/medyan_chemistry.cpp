// Translator (io/medyan_translator.hpp): the chemistry file's species and reactions.

#include <fmt/format.h>

#include <cctype>
#include <cmath>

#include "core/error.hpp"
#include "io/medyan_translator.hpp"

namespace cortex::medyan {

void Translator::speciesOfChemistry() {
  for (const Entry& e : chemistry_) {
    const std::string& k = e.upper;
    if (k == "SPECIESDIFFUSING" || k == "SPECIESBULK") {
      used_.insert(&e);
      const bool bulk = k == "SPECIESBULK";
      if (e.values.empty()) throw InputError(fmt::format("{}: {}: the species name is missing", e.where, e.key));
      const std::string& name = e.values[0];
      if (species_.count(name)) throw InputError(fmt::format("{}: species '{}' is defined twice", e.where, name));
      for (char c : name)
        if (std::isspace(static_cast<unsigned char>(c)) || c == '/' || c == '+' || c == '>' || c == '"')
          throw InputError(fmt::format("{}: species name '{}': cortex names have no spaces, '/', '+', '>'", e.where, name));
      species_[name] = {bulk ? "BULK" : "DIFFUSING", e.where};
      const long long copies = count(number(e, 1, "COPYNUMBER"), e.where, e.key + " COPYNUMBER");
      double diffusion = 0;
      std::size_t next = 2;
      if (!bulk) diffusion = number(e, next++, "DIFFCOEFF");
      if (diffusion < 0) throw InputError(fmt::format("{}: {}: DIFFCOEFF must be >= 0", e.where, e.key));
      const double release = next < e.values.size() && toNumber(e.values[next]) ? *toNumber(e.values[next]) : 0.0;
      const double removal =
          next + 1 < e.values.size() && toNumber(e.values[next + 1]) ? *toNumber(e.values[next + 1]) : 0.0;
      std::string qualifier;
      for (const auto& v : e.values)
        if (!toNumber(v) && &v != &e.values[0]) qualifier = upperCase(v);
      std::ostringstream s;
      s << "\n[[species]]\nname = " << quoted(name) << "\ncopies = " << copies << "\n";
      if (bulk) {
        // cortex has no well-mixed species: a fast-diffusing one stands in for it.
        const double d_fast = 1e8;
        s << "diffusion = " << num(d_fast) << "    # SPECIESBULK: well mixed, approximated\n";
        skip(e.where, fmt::format("SPECIESBULK {}: cortex has no well-mixed species; written as a diffusing species "
                                  "with D = {:g} nm²/s (approximation)",
                                  name, d_fast));
      } else {
        s << "diffusion = " << num(diffusion) << "\n";
        done(e.where, fmt::format("SPECIESDIFFUSING {} -> [[species]] copies = {} (whole box), diffusion = {:g} nm²/s "
                                  "(MEDYAN >= 5.1 gives D in nm²/s as cortex does)",
                                  name, copies, diffusion));
      }
      if (release > 0)
        skip(e.where, fmt::format("{}: RELEASETIME {} s: cortex places every copy at t = 0", name, release));
      if (removal > 0) skip(e.where, fmt::format("{}: REMOVALTIME {} s: cortex never removes species", name, removal));
      if (qualifier == "AVG") skip(e.where, fmt::format("{}: AVG qualifier: copies are exact in cortex", name));
      if (qualifier == "CONST") skip(e.where, fmt::format("{}: CONST qualifier: cortex's species change copy numbers", name));
      species_toml_[name] = s.str();
      diffusing_order_.push_back(name);
    } else if (k.rfind("SPECIES", 0) == 0) {
      used_.insert(&e);
      const std::string kind = k.substr(7);
      static const std::set<std::string> kinds = {"FILAMENT", "PLUSEND", "MINUSEND", "BOUND",
                                                  "LINKER",   "MOTOR",   "BRANCHER"};
      if (!kinds.count(kind)) {
        skip(e.where, fmt::format("{}: species kind not known to cortex", e.key));
        continue;
      }
      if (e.values.empty()) throw InputError(fmt::format("{}: {}: the species name is missing", e.where, e.key));
      const std::string& name = e.values[0];
      if (species_.count(name)) throw InputError(fmt::format("{}: species '{}' is defined twice", e.where, name));
      species_[name] = {kind, e.where};
      if (e.values.size() > 1 && toNumber(e.values[1]) && *toNumber(e.values[1]) != 0)
        skip(e.where, fmt::format("{} {}: filament type {}: only filament type 0 is translated", e.key, name,
                                  e.values[1]));
    } else if (k == "LINKERBINDINGSITE" || k == "MOTORBINDINGSITE" || k == "BRANCHERBINDINGSITE") {
      used_.insert(&e);
      // Which species binds is in the reactions; this only names it once more.
      if (e.values.empty()) throw InputError(fmt::format("{}: {}: the bound species is missing", e.where, e.key));
    }
  }
}

void Translator::setMonomer(const Entry& e, const std::string& name) {
  if (monomer_.empty()) monomer_ = name;
  if (monomer_ != name)
    throw InputError(fmt::format("{}: {}: a second monomer species '{}' ('{}' came first): cortex has one monomer "
                                 "species per filament type",
                                 e.where, e.key, name, monomer_));
}

bool Translator::filamentTypeOk(const Entry& e, const Reaction& r) {
  if (r.filament_type != 0) {
    skip(e.where, fmt::format("{}: filament type {}: only filament type 0 is translated", e.key, r.filament_type));
    return false;
  }
  if (r.dissipation) skip(e.where, fmt::format("{}: the dissipation-tracking field is ignored", e.key));
  return true;
}

void Translator::requireSpecies(const Entry& e, const Ref& r, std::initializer_list<const char*> kinds) const {
  const auto it = species_.find(r.name);
  if (it == species_.end())
    throw InputError(fmt::format("{}: {}: species '{}' is not defined before (MEDYAN's rule)", e.where, e.key, r.name));
  const std::string& kind = it->second.kind;
  if (r.type != kind)
    throw InputError(fmt::format("{}: {}: '{}:{}', but {} is a {} species", e.where, e.key, r.name, r.type, r.name, kind));
  bool allowed = false;
  for (const char* k : kinds) allowed = allowed || kind == k;
  if (!allowed)
    throw InputError(fmt::format("{}: {}: {} ({}) cannot stand at this place of the reaction", e.where, e.key, r.name, kind));
}

void Translator::reactionsOfChemistry() {
  for (const Entry& e : chemistry_) {
    const std::string& k = e.upper;
    if (k == "POLYMERIZATIONREACTION" || k == "DEPOLYMERIZATIONREACTION")
      translatePolymerization(e);
    else if (k == "NUCLEATIONREACTION")
      translateNucleation(e);
    else if (k == "LINKERREACTION" || k == "MOTORREACTION")
      translateBinder(e);
    else if (k == "MOTORWALKINGREACTION")
      translateMotorWalking(e);
    else if (k == "BRANCHINGREACTION")
      translateBranching(e);
    else if (k == "GENREACTION" || k == "BULKREACTION")
      translateGeneralReaction(e);
    else if (k == "AGINGREACTION" || k == "DESTRUCTIONREACTION" || k == "SEVERINGREACTION")
      skip(e.where, fmt::format("{}: not in cortex's filament model (no nucleotide states, severing or filament "
                                "removal)",
                                e.key));
    else
      continue;  // not a reaction
    used_.insert(&e);
  }
}

void Translator::translatePolymerization(const Entry& e) {
  const std::string& k = e.upper;
  const Reaction r = parseReaction(e, true);
  if (!filamentTypeOk(e, r)) return;
  const bool poly = k == "POLYMERIZATIONREACTION";
  if (r.reactants.size() != 2 || r.products.size() != 2 || r.params.size() != 1)
    throw InputError(fmt::format("{}: {}: expected 2 reactants, 2 products and one rate", e.where, e.key));
  const Ref& free = poly ? r.reactants[0] : r.products[0];
  const Ref& end = poly ? r.reactants[1] : r.products[1];
  requireSpecies(e, free, {"DIFFUSING", "BULK"});
  requireSpecies(e, end, {"PLUSEND", "MINUSEND"});
  setMonomer(e, free.name);
  const bool plus = end.type == "PLUSEND";
  const double rate = r.params[0];
  if (rate < 0) throw InputError(fmt::format("{}: {}: the rate must be >= 0", e.where, e.key));
  any_filament_rate_ = true;
  if (poly) {
    (plus ? plus_on_ : minus_on_) = rate * per_uM_;
    done(e.where, fmt::format("{} ({}) {} /s per copy x {:.4g} copies/µM -> filament_type.{} = {:.4g} /(µM·s)",
                              e.key, end.type, rate, per_uM_, plus ? "plus_on" : "minus_on", rate * per_uM_));
  } else {
    (plus ? plus_off_ : minus_off_) = rate;
    done(e.where, fmt::format("{} ({}) -> filament_type.{} = {} /s", e.key, end.type,
                              plus ? "plus_off" : "minus_off", rate));
  }
}

void Translator::translateNucleation(const Entry& e) {
  const Reaction r = parseReaction(e, true);
  if (!filamentTypeOk(e, r)) return;
  if (r.reactants.size() != 2 || r.params.size() != 1)
    throw InputError(fmt::format("{}: {}: expected 2 reactants and one rate", e.where, e.key));
  if (r.reactants[0].name != r.reactants[1].name) {
    skip(e.where, fmt::format("{}: {} + {}: cortex nucleates from two monomers of one species only", e.key,
                              r.reactants[0].name, r.reactants[1].name));
    return;
  }
  requireSpecies(e, r.reactants[0], {"DIFFUSING", "BULK"});
  setMonomer(e, r.reactants[0].name);
  nucleation_ = r.params[0] * per_uM_;
  any_filament_rate_ = true;
  done(e.where, fmt::format("NUCLEATIONREACTION {} /s per copy pair x {:.4g} -> filament_type.nucleation_rate = "
                            "{:.4g} /(µM·s)",
                            r.params[0], per_uM_, nucleation_));
}

void Translator::translateBinder(const Entry& e) {
  const std::string& k = e.upper;
  const Reaction r = parseReaction(e, true);
  if (!filamentTypeOk(e, r)) return;
  if (r.reactants.size() != 3 || r.products.size() != 2 || r.params.size() != 4 || !r.reversible)
    throw InputError(fmt::format("{}: {}: expected B:BOUND:1 + B:BOUND:2 + X:DIFFUSING <-> P:{}:1 + P:{}:2 "
                                 "ONRATE OFFRATE RMIN RMAX",
                                 e.where, e.key, k == "LINKERREACTION" ? "LINKER" : "MOTOR",
                                 k == "LINKERREACTION" ? "LINKER" : "MOTOR"));
  requireSpecies(e, r.reactants[2], {"DIFFUSING", "BULK"});
  Binder b;
  b.species = r.reactants[2].name;
  b.where = e.where;
  b.on = r.params[0], b.off = r.params[1], b.rmin = r.params[2], b.rmax = r.params[3];
  if (b.on < 0 || b.off < 0 || b.rmin < 0 || b.rmax <= b.rmin)
    throw InputError(fmt::format("{}: {}: rates must be >= 0 and 0 <= RMIN < RMAX", e.where, e.key));
  (k == "LINKERREACTION" ? linkers_ : motors_).push_back(b);
}

void Translator::translateMotorWalking(const Entry& e) {
  const Reaction r = parseReaction(e, true);
  if (!filamentTypeOk(e, r)) return;
  if (r.reactants.size() != 2 || r.products.size() != 2 || r.params.size() != 1)
    throw InputError(fmt::format("{}: {}: expected M:MOTOR:N + B:BOUND:N+1 -> M:MOTOR:N+1 + B:BOUND:N RATE",
                                 e.where, e.key));
  if (upperCase(r.reactants[0].pos) != "N" || upperCase(r.products[0].pos) != "N+1") {
    skip(e.where, "MOTORWALKINGREACTION towards the minus end (N+1 -> N): cortex's motors walk to plus ends only");
    return;
  }
  // Walking applies to the motor species whose reaction came first (one per motor type).
  bool placed = false;
  for (Binder& m : motors_)
    if (!m.walks) {
      m.walks = true, m.walk = r.params[0], placed = true;
      break;
    }
  if (!placed) skip(e.where, "MOTORWALKINGREACTION without a MOTORREACTION before it");
  else
    done(e.where, "MOTORWALKINGREACTION: towards plus ends (rate below, with MOTORREACTION)");
}

void Translator::translateBranching(const Entry& e) {
  const Reaction r = parseReaction(e, true);
  if (!filamentTypeOk(e, r)) return;
  if (r.reactants.size() != 3 || r.params.size() < 2)
    throw InputError(fmt::format("{}: {}: expected A + G + B:BOUND <-> BR:BRANCHER + P:PLUSEND ONRATE OFFRATE "
                                 "ZONE DIST",
                                 e.where, e.key));
  const Ref& arp = r.reactants[0];
  const Ref& g = r.reactants[1];
  requireSpecies(e, arp, {"DIFFUSING", "BULK"});
  requireSpecies(e, g, {"DIFFUSING", "BULK"});
  setMonomer(e, g.name);
  std::string zone = "ALL";
  for (const auto& v : e.values)
    if (upperCase(v) == "BOUNDARY" || upperCase(v) == "TOPBOUNDARY") zone = upperCase(v);
  if (zone != "ALL")
    skip(e.where, fmt::format("BRANCHINGREACTION nucleation zone {}: cortex branches everywhere (ALL)", zone));
  const double rate = r.params[0] * per_uM_ * per_uM_;
  branchers_ << "\n[[brancher]]\nspecies = " << quoted(arp.name) << "\nrate = " << num(rate)
            << "\nunbranch_rate = " << num(r.params[1]) << "\n";
  ++n_branchers_;
  done(e.where, fmt::format("BRANCHINGREACTION on {} /s per copy pair x ({:.4g})² -> brancher.rate = {:.4g} "
                            "/(µM²·s); off -> unbranch_rate = {} /s",
                            r.params[0], per_uM_, rate, r.params[1]));
}

void Translator::translateGeneralReaction(const Entry& e) {
  const Reaction r = parseReaction(e, false);
  if (r.params.size() != 1) throw InputError(fmt::format("{}: {}: expected one rate at the end", e.where, e.key));
  for (const auto& x : r.reactants) requireSpecies(e, x, {"DIFFUSING", "BULK"});
  for (const auto& x : r.products) requireSpecies(e, x, {"DIFFUSING", "BULK"});
  const int order = static_cast<int>(r.reactants.size());
  if (order > 2) {
    skip(e.where, fmt::format("{} of order {}: cortex's reactions have order <= 2", e.key, order));
    return;
  }
  // A per-copy rate k (propensity k Π n_i) is k (N_A V)^(order-1) in concentration units.
  const double rate = r.params[0] * std::pow(per_uM_, order - 1);
  std::string eq;
  for (std::size_t i = 0; i < r.reactants.size(); ++i) eq += (i ? " + " : "") + r.reactants[i].name;
  eq += " ->";
  for (std::size_t i = 0; i < r.products.size(); ++i) eq += (i ? " + " : " ") + r.products[i].name;
  if (order == 2 && r.reactants[0].name == r.reactants[1].name)
    eq = "2 " + r.reactants[0].name + eq.substr(eq.find(" ->"));
  reactions_ << "\n[[reaction]]\nequation = " << quoted(eq) << "\nrate = " << num(rate) << "\n";
  const char* units[] = {"µM/s", "1/s", "1/(µM·s)"};
  done(e.where, fmt::format("{} {} -> [[reaction]] rate = {:.4g} {} (per-copy {} x (N_A V)^{})", e.key, eq, rate,
                            units[order], r.params[0], order - 1));
  if (r.dissipation) skip(e.where, fmt::format("{}: the dissipation-tracking field is ignored", e.key));
}

}  // namespace cortex::medyan
