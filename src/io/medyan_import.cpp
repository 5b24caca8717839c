#include "io/medyan_import.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/medyan_input.hpp"

namespace cortex {
namespace {

namespace fs = std::filesystem;
using medyan::Entry;
using medyan::number;
using medyan::parseFile;
using medyan::parseReaction;
using medyan::Reaction;
using medyan::Ref;
using medyan::toNumber;
using medyan::upperCase;

constexpr double kCopiesPerMicromolarFemtolitre = 602.214076;  // N_A · 1 µM · 1 fL

// A number as TOML: always a float literal.
std::string num(double x) {
  std::string s = fmt::format("{}", x);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

struct Species {
  std::string kind;  // DIFFUSING, BULK, FILAMENT, PLUSEND, MINUSEND, BOUND, LINKER, MOTOR, BRANCHER
  std::string where;
};

struct Binder {  // a linker or motor type
  std::string species, where;
  double on = 0, off = 0, rmin = 0, rmax = 0, walk = 0;
  bool walks = false;
};

class Translator {
 public:
  Translator(std::vector<Entry> system, std::vector<Entry> chemistry)
      : system_(std::move(system)), chemistry_(std::move(chemistry)) {}

  MedyanImport run(const std::string& system_name, const std::string& chemistry_name);

 private:
  std::vector<Entry> system_, chemistry_;
  std::set<const Entry*> used_;
  MedyanImport out_;
  std::ostringstream toml_;  // the config, section by section in the order run() calls them

  // Geometry (compartments).
  double compartment_size_ = 0;            // nm
  std::array<double, 3> shape_{}, box_{};  // compartments per axis; the grid's extent, nm
  double per_uM_ = 0;                      // copies per µM in one compartment
  // The chemistry file's species and reactions.
  std::map<std::string, Species> species_;
  std::vector<std::string> diffusing_order_;
  std::map<std::string, std::string> species_toml_;
  std::string monomer_;
  double plus_on_ = 0, minus_on_ = 0, plus_off_ = 0, minus_off_ = 0, nucleation_ = 0;
  bool any_filament_rate_ = false;
  std::vector<Binder> linkers_, motors_;
  std::ostringstream reactions_, branchers_;
  int n_branchers_ = 0;
  // The filament type.
  double monomer_size_ = 2.7, cylinder_size_ = 108.0;  // nm
  int cylinder_monomers_ = 40;
  bool want_filaments_ = false;
  int spacing_ = 10;  // monomers between binding sites

  // The sections, in the order of the config.
  void geometry(const std::string& system_name);
  void runControl();
  void minimizer();
  void speciesOfChemistry();
  void reactionsOfChemistry();
  void translatePolymerization(const Entry& e);
  void translateNucleation(const Entry& e);
  void translateBinder(const Entry& e);
  void translateMotorWalking(const Entry& e);
  void translateBranching(const Entry& e);
  void translateGeneralReaction(const Entry& e);
  void filamentType();
  void boundary();
  void bindingSites();
  void linkers();
  void motors();
  // The [[linker]] or [[motor]] table's head, shared by both: species, range, rates.
  void openBinder(const char* table, const char* reaction, const Binder& b, std::size_t i);
  void branchers();
  void everythingElse();

  void requireSpecies(const Entry& e, const Ref& r, std::initializer_list<const char*> kinds) const;
  void setMonomer(const Entry& e, const std::string& name);
  bool filamentTypeOk(const Entry& e, const Reaction& r);
  // Entry i of a list keyword (one value per linker or motor type), or nothing where
  // the list is shorter (value() would call that missing).
  std::optional<double> listValue(const char* key, std::size_t i) {
    const Entry* e = find(key);
    if (!e || i >= e->values.size()) return std::nullopt;
    return number(*e, i, "the value");
  }

  const Entry* find(const std::string& upper) {
    const Entry* found = nullptr;
    for (const Entry& e : system_)
      if (e.upper == upper) {
        used_.insert(&e);
        if (!e.values.empty()) found = &e;  // the last non-empty one counts
      }
    return found;
  }
  std::optional<double> value(const std::string& upper, std::size_t i = 0) {
    const Entry* e = find(upper);
    if (!e) return std::nullopt;
    return number(*e, i, "the value");
  }
  std::optional<std::string> word(const std::string& upper) {
    const Entry* e = find(upper);
    if (!e) return std::nullopt;
    return e->values.front();
  }
  std::string whereOf(const std::string& upper) {
    for (const Entry& e : system_)
      if (e.upper == upper && !e.values.empty()) return e.where;
    return "";
  }
  void done(const std::string& where, const std::string& what) { out_.translated.push_back(where + ": " + what); }
  void skip(const std::string& where, const std::string& what) { out_.untranslated.push_back(where + ": " + what); }
};

MedyanImport Translator::run(const std::string& system_name, const std::string& chemistry_name) {
  geometry(system_name);
  runControl();
  minimizer();
  speciesOfChemistry();
  reactionsOfChemistry();
  for (const auto& name : diffusing_order_) toml_ << species_toml_[name];
  filamentType();
  boundary();
  bindingSites();
  linkers();
  motors();
  branchers();
  toml_ << reactions_.str();
  everythingElse();
  std::ostringstream head;
  head << "# Translated by `cortex import-medyan` from " << system_name << " and " << chemistry_name
       << ".\n# The mapping and the model differences: docs/medyan.md.\n";
  if (out_.untranslated.empty()) {
    head << "# Everything was translated.\n";
  } else {
    head << "# Not translated (" << out_.untranslated.size() << "):\n";
    for (const auto& u : out_.untranslated) head << "#   " << u << "\n";
  }
  head << "\n";
  out_.toml = head.str() + toml_.str();
  return out_;
}

void Translator::geometry(const std::string& system_name) {
  const auto nx = value("NX"), ny = value("NY"), nz = value("NZ");
  const auto sx = value("COMPARTMENTSIZEX"), sy = value("COMPARTMENTSIZEY"), sz = value("COMPARTMENTSIZEZ");
  if (!nx || !ny || !nz || !sx || !sy || !sz)
    throw InputError(fmt::format("{}: NX, NY, NZ and COMPARTMENTSIZEX/Y/Z are required (MEDYAN's manual: all "
                                 "geometry parameters must be set)",
                                 system_name));
  for (double n : {*nx, *ny, *nz})
    if (n < 1 || n != std::floor(n))
      throw InputError(fmt::format("{}: NX, NY, NZ must be integers >= 1", whereOf("NX")));
  for (double s : {*sx, *sy, *sz})
    if (s <= 0) throw InputError(fmt::format("{}: COMPARTMENTSIZE must be > 0 nm", whereOf("COMPARTMENTSIZEX")));
  if (*sx != *sy || *sx != *sz)
    throw InputError(fmt::format("{}: compartments of {} x {} x {} nm: cortex's compartments are cubes (equal "
                                 "COMPARTMENTSIZEX, Y and Z)",
                                 whereOf("COMPARTMENTSIZEX"), *sx, *sy, *sz));
  const double h = *sx;
  compartment_size_ = h;
  shape_ = {*nx, *ny, *nz};
  const double volume_fl = h * h * h * 1e-9;
  per_uM_ = kCopiesPerMicromolarFemtolitre * volume_fl;  // copies per µM in one compartment
  box_ = {*nx * h, *ny * h, *nz * h};
  done(whereOf("NX"), fmt::format("NX, NY, NZ, COMPARTMENTSIZEX/Y/Z -> compartments.shape = [{}, {}, {}], "
                                  "compartments.size = {} nm (N_A V = {:.4g} copies per µM per compartment)",
                                  *nx, *ny, *nz, h, per_uM_));
}

void Translator::runControl() {
  toml_ << "[simulation]\n";
  if (const auto t = value("RUNTIME")) {
    toml_ << "end_time = " << num(*t) << "\n";
    done(whereOf("RUNTIME"), fmt::format("RUNTIME -> simulation.end_time = {} s", *t));
  }
  if (const auto t = value("MINIMIZATIONTIME")) {
    toml_ << "chemistry_window = " << num(*t) << "\n";
    done(whereOf("MINIMIZATIONTIME"), fmt::format("MINIMIZATIONTIME -> simulation.chemistry_window = {} s", *t));
  }
  if (const auto t = value("NEIGHBORLISTTIME")) {
    const auto m = value("MINIMIZATIONTIME");
    if (m && *m == *t)
      done(whereOf("NEIGHBORLISTTIME"), "NEIGHBORLISTTIME: cortex refreshes binding pairs and neighbour lists after "
                                        "every minimization (= MINIMIZATIONTIME here)");
    else
      skip(whereOf("NEIGHBORLISTTIME"), "NEIGHBORLISTTIME differs from MINIMIZATIONTIME: cortex refreshes binding "
                                        "pairs after every minimization");
  }
  if (const auto t = value("SNAPSHOTTIME")) {
    toml_ << "snapshot_interval = " << num(*t) << "\n";
    done(whereOf("SNAPSHOTTIME"), fmt::format("SNAPSHOTTIME -> simulation.snapshot_interval = {} s", *t));
  }
  for (const char* k : {"RUNSTEPS", "SNAPSHOTSTEPS", "MINIMIZATIONSTEPS", "NEIGHBORLISTSTEPS", "INITIALSLOWDOWNTIME"})
    if (find(k)) skip(whereOf(k), fmt::format("{}: cortex runs by time (RUNTIME, MINIMIZATIONTIME) only", k));
}

void Translator::minimizer() {
  toml_ << "\n[mechanics]\nminimizer = \"cg\"\n";
  if (const auto cg = word("CONJUGATEGRADIENT")) {
    if (upperCase(*cg) == "POLAKRIBIERE")
      done(whereOf("CONJUGATEGRADIENT"), "CONJUGATEGRADIENT POLAKRIBIERE -> mechanics.minimizer = \"cg\"");
    else
      skip(whereOf("CONJUGATEGRADIENT"), fmt::format("CONJUGATEGRADIENT {}: cortex's CG is Polak-Ribiere; "
                                                     "minimizer = \"cg\" written",
                                                     *cg));
  }
  if (const auto g = value("GRADIENTTOLERANCE")) {
    toml_ << "force_tolerance = " << num(*g) << "\n";
    done(whereOf("GRADIENTTOLERANCE"), fmt::format("GRADIENTTOLERANCE -> mechanics.force_tolerance = {} pN", *g));
  }
  if (const auto d = value("MAXDISTANCE")) {
    toml_ << "max_step = " << num(*d) << "\n";
    done(whereOf("MAXDISTANCE"), fmt::format("MAXDISTANCE -> mechanics.max_step = {} nm", *d));
  }
  if (find("LAMBDAMAX"))
    skip(whereOf("LAMBDAMAX"), "LAMBDAMAX: cortex's line search has no such bound (max_step limits the moves)");
  find("TRY-TO-RECOVER-IN-LINE-SEARCH-ERROR");

  toml_ << "\n[compartments]\nsize = " << num(compartment_size_)
        << fmt::format("\nshape = [{}, {}, {}]\n", shape_[0], shape_[1], shape_[2]);
  if (const auto a = word("CALGORITHM")) {
    const std::string u = upperCase(*a);
    toml_ << "\n[chemistry]\nengine = " << (u == "GILLESPIE" ? "\"direct\"" : "\"nsm\"") << "\n";
    done(whereOf("CALGORITHM"),
         fmt::format("CALGORITHM {} -> chemistry.engine = {} (both exact stochastic simulation)", *a,
                     u == "GILLESPIE" ? "\"direct\"" : "\"nsm\" (next-subvolume method)"));
  }
}

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
      const double copies = number(e, 1, "COPYNUMBER");
      if (copies < 0 || copies != std::floor(copies))
        throw InputError(fmt::format("{}: {}: COPYNUMBER must be an integer >= 0", e.where, e.key));
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
      s << "\n[[species]]\nname = " << quoted(name) << "\ncopies = " << static_cast<long long>(copies) << "\n";
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

void Translator::filamentType() {
  const bool filaments = species_.end() != std::find_if(species_.begin(), species_.end(),
                                                       [](const auto& s) { return s.second.kind == "FILAMENT"; });
  monomer_size_ = value("MONOMERSIZE").value_or(2.7);
  cylinder_size_ = value("CYLINDERSIZE").value_or(108.0);
  cylinder_monomers_ = static_cast<int>(std::lround(cylinder_size_ / monomer_size_));
  if (find("NUMFILAMENTTYPES")) {
    const double n = *value("NUMFILAMENTTYPES");
    if (n != 1) skip(whereOf("NUMFILAMENTTYPES"), "NUMFILAMENTTYPES > 1: only filament type 0 is translated");
  }
  want_filaments_ = filaments || value("NUMFILAMENTS").value_or(0) > 0 || !linkers_.empty() || !motors_.empty();
  if (want_filaments_) {
    toml_ << "\n[[filament_type]]\nname = \"actin\"\n";
    if (!monomer_.empty()) toml_ << "monomer_species = " << quoted(monomer_) << "\n";
    toml_ << "monomer_size = " << num(monomer_size_) << "\ncylinder_monomers = " << cylinder_monomers_ << "\n";
    if (find("MONOMERSIZE")) done(whereOf("MONOMERSIZE"), fmt::format("MONOMERSIZE -> filament_type.monomer_size = {} nm", monomer_size_));
    if (find("CYLINDERSIZE"))
      done(whereOf("CYLINDERSIZE"), fmt::format("CYLINDERSIZE {} nm / MONOMERSIZE -> filament_type.cylinder_monomers = {}",
                                                cylinder_size_, cylinder_monomers_));
    if (const auto kf = value("FSTRETCHINGK")) {
      toml_ << "stretching_stiffness = " << num(*kf) << "\n";
      done(whereOf("FSTRETCHINGK"), fmt::format("FSTRETCHINGK -> filament_type.stretching_stiffness = {} pN/nm", *kf));
    }
    for (const char* t : {"FSTRETCHINGTYPE", "FSTRETCHINGFFTYPE"})
      if (const auto w = word(t); w && upperCase(*w) != "HARMONIC")
        skip(whereOf(t), fmt::format("{} {}: cortex's stretching is harmonic", t, *w));
    std::string bending_type = "COSINE";
    for (const char* t : {"FBENDINGTYPE", "FBENDINGFFTYPE"})
      if (const auto w = word(t)) bending_type = upperCase(*w);
    if (const auto kb = value("FBENDINGK")) {
      if (bending_type == "COSINE") {
        toml_ << "bending_stiffness = " << num(*kb) << "\n";
        done(whereOf("FBENDINGK"), fmt::format("FBENDINGK (COSINE) -> filament_type.bending_stiffness = {} pN·nm", *kb));
      } else {
        skip(whereOf("FBENDINGK"), fmt::format("FBENDINGK with {} bending: cortex's bending is K(1 - cos θ); the "
                                               "default 672 pN·nm is kept",
                                               bending_type));
      }
    }
    if (const auto th = value("FBENDINGTHETA"); th && *th != 0)
      skip(whereOf("FBENDINGTHETA"), "FBENDINGTHETA != 0: cortex's filaments are straight at rest");
    if (any_filament_rate_) {
      toml_ << "plus_on = " << num(plus_on_) << "\nplus_off = " << num(plus_off_) << "\nminus_on = " << num(minus_on_)
           << "\nminus_off = " << num(minus_off_) << "\n";
      if (nucleation_ > 0) toml_ << "nucleation_rate = " << num(nucleation_) << "\n";
    }
    // Excluded volume
    std::string vtype;
    if (const auto w = word("VOLUMEFFTYPE")) vtype = upperCase(*w);
    const auto vk = value("VOLUMEK");
    const auto vc = value("VOLUMECUTOFF");
    if ((vtype == "INTEGRAL" || vtype == "REPULSION") && vk && *vk > 0) {
      // MEDYAN's E = k ∫∫ dl1 dl2 / r⁴ pushes two crossing cylinders at distance d apart
      // with 2πk/d³; cortex's harmonic contact starts where that force is 1 pN.
      const double d0 = std::cbrt(2.0 * M_PI * *vk / 1.0);
      toml_ << "excluded_volume_distance = " << num(std::round(d0 * 100.0) / 100.0) << "\n";
      skip(whereOf("VOLUMEK"),
           fmt::format("VOLUMEFFTYPE {} (VOLUMEK {}, VOLUMECUTOFF {}): MEDYAN's k/r⁴ cylinder repulsion is not cortex's; "
                       "approximated by the harmonic contact (10 pN/nm) below filament_type.excluded_volume_distance = "
                       "{:.2f} nm, where two crossing cylinders feel 2πk/d³ = 1 pN",
                       vtype, *vk, vc ? fmt::format("{}", *vc) : "-", d0));
    } else if (!vtype.empty() || vk || vc) {
      skip(whereOf(vk ? "VOLUMEK" : "VOLUMEFFTYPE"),
           fmt::format("VOLUMEFFTYPE {} (VOLUMEK {}, VOLUMECUTOFF {}): not translated; the harmonic contact "
                       "(10 pN/nm below 7 nm) is kept",
                       vtype.empty() ? "-" : vtype, vk ? fmt::format("{}", *vk) : "-",
                       vc ? fmt::format("{}", *vc) : "-"));
    }
    find("VOLUME-EXCLUSION-MONOMER-INTERVAL");
    // Brownian ratchet
    if (const auto len = value("DFPOLYMERIZATIONLEN")) {
      if (std::abs(*len - monomer_size_) < 1e-9)
        done(whereOf("DFPOLYMERIZATIONLEN"),
             "DFPOLYMERIZATIONTYPE BROWRATCHET, DFPOLYMERIZATIONLEN = MONOMERSIZE: cortex's ratchet exp(-f δ/kBT)");
      else
        skip(whereOf("DFPOLYMERIZATIONLEN"), fmt::format("DFPOLYMERIZATIONLEN {} nm: cortex's ratchet length is the "
                                                         "monomer size {} nm",
                                                         *len, monomer_size_));
    }
    find("DFPOLYMERIZATIONTYPE");

    // Initial filaments
    if (const auto n = value("NUMFILAMENTS"); n && *n > 0) {
      const double cyl = value("FILAMENTLENGTH").value_or(1.0);
      toml_ << "\n[[filaments]]\ntype = \"actin\"\ncount = " << static_cast<long long>(*n)
           << "\nlength = " << num(cyl * cylinder_size_) << "\n";
      done(whereOf("NUMFILAMENTS"), fmt::format("NUMFILAMENTS, FILAMENTLENGTH {} cylinders -> filaments.count = {}, "
                                                "filaments.length = {} nm (random, straight)",
                                                cyl, *n, cyl * cylinder_size_));
      if (const auto t = value("FILAMENTTYPE"); t && *t != 0)
        skip(whereOf("FILAMENTTYPE"), "FILAMENTTYPE != 0: only filament type 0 is translated");
      if (const auto p = word("PROJECTIONTYPE"); p && upperCase(*p) != "STRAIGHT")
        skip(whereOf("PROJECTIONTYPE"), fmt::format("PROJECTIONTYPE {}: cortex's initial filaments are straight", *p));
    }
    find("FILAMENTTYPTE");
    if (find("FILAMENTFILE"))
      skip(whereOf("FILAMENTFILE"), "FILAMENTFILE: reading filament coordinates is not supported");
  }
}

void Translator::boundary() {
  if (const auto shape = word("BOUNDARYSHAPE")) {
    const std::string s = upperCase(*shape);
    std::ostringstream b;
    if (s == "CUBIC") {
      // MEDYAN's manual: "The CUBIC BOUNDARYSHAPE creates boundary planes 25nm in from the
      // faces of compartment grid."
      const double inset = 25.0;
      if (box_[0] <= 2 * inset || box_[1] <= 2 * inset || box_[2] <= 2 * inset)
        throw InputError(fmt::format("{}: BOUNDARYSHAPE CUBIC: the grid is too small for walls 25 nm inside it",
                                     whereOf("BOUNDARYSHAPE")));
      b << "\n[boundary]\nshape = \"box\"\nmin = [" << num(inset) << ", " << num(inset) << ", " << num(inset)
        << "]\nmax = [" << num(box_[0] - inset) << ", " << num(box_[1] - inset) << ", " << num(box_[2] - inset) << "]\n";
      done(whereOf("BOUNDARYSHAPE"), "BOUNDARYSHAPE CUBIC -> boundary.shape = \"box\", walls 25 nm inside the "
                                     "compartment grid's faces (MEDYAN's manual)");
    } else if (s == "SPHERICAL") {
      const auto d = value("BOUNDARYDIAMETER");
      if (!d) throw InputError(fmt::format("{}: BOUNDARYSHAPE SPHERICAL needs BOUNDARYDIAMETER", whereOf("BOUNDARYSHAPE")));
      b << "\n[boundary]\nshape = \"sphere\"\ncenter = [" << num(box_[0] / 2) << ", " << num(box_[1] / 2) << ", "
        << num(box_[2] / 2) << "]\nradius = " << num(*d / 2) << "\n";
      done(whereOf("BOUNDARYSHAPE"), fmt::format("BOUNDARYSHAPE SPHERICAL, BOUNDARYDIAMETER -> boundary.shape = "
                                                 "\"sphere\", radius = {} nm at the grid's centre",
                                                 *d / 2));
    } else {
      skip(whereOf("BOUNDARYSHAPE"), fmt::format("BOUNDARYSHAPE {}: cortex has box and sphere boundaries only", *shape));
    }
    if (!b.str().empty() && want_filaments_) {
      toml_ << b.str();
      if (const auto k = value("BOUNDARYINTERACTIONK")) {
        toml_ << "repulsion = " << num(*k) << "\n";
        done(whereOf("BOUNDARYINTERACTIONK"), fmt::format("BOUNDARYINTERACTIONK -> boundary.repulsion = {} pN", *k));
      }
      if (const auto l = value("BOUNDARYSCREENLENGTH")) {
        toml_ << "screening_length = " << num(*l) << "\n";
        done(whereOf("BOUNDARYSCREENLENGTH"), fmt::format("BOUNDARYSCREENLENGTH -> boundary.screening_length = {} nm", *l));
      }
      if (find("BOUNDARYCUTOFF"))
        done(whereOf("BOUNDARYCUTOFF"), "BOUNDARYCUTOFF: cortex keeps every wall term up to 50 screening lengths");
      if (const auto t = word("BOUNDARYFFTYPE"); t && upperCase(*t) != "REPULSIONEXP")
        skip(whereOf("BOUNDARYFFTYPE"), fmt::format("BOUNDARYFFTYPE {}: cortex's wall is REPULSIONEXP", *t));
    }
  }
  find("BOUNDARYDIAMETER");
  for (const char* k : {"BOUNDARYMOVE", "BMOVESPEED", "BMOVESTARTTIME", "BMOVEENDTIME"})
    if (const auto w = word(k); w && upperCase(*w) != "NONE")
      skip(whereOf(k), fmt::format("{}: moving boundaries are not supported", k));
}

void Translator::bindingSites() {
  if (const auto n = value("NUMBINDINGSITES")) {
    spacing_ = std::max(1, static_cast<int>(std::lround(cylinder_monomers_ / *n)));
    const bool exact = std::abs(cylinder_monomers_ / *n - spacing_) < 1e-9;
    (exact ? out_.translated : out_.untranslated)
        .push_back(fmt::format("{}: NUMBINDINGSITES {} per {}-monomer cylinder -> site_spacing = {} monomers{}",
                               whereOf("NUMBINDINGSITES"), *n, cylinder_monomers_, spacing_,
                               exact ? "" : " (rounded: sites are spaced evenly along whole filaments in cortex)"));
  }
  if (find("LINKERBINDINGSKIP"))
    skip(whereOf("LINKERBINDINGSKIP"), "LINKERBINDINGSKIP: linkers and motors share the site spacing here");
  if (const auto w = word("ALLOW-SAME-FILAMENT-PAIR-BINDING"); w && (*w == "true" || *w == "1"))
    skip(whereOf("ALLOW-SAME-FILAMENT-PAIR-BINDING"), "allow-same-filament-pair-binding true: cortex binds two "
                                                      "different filaments only");
}

void Translator::openBinder(const char* table, const char* reaction, const Binder& b, std::size_t i) {
  // A per-copy rate for one site pair in one compartment: cortex's per-pair rate in
  // 1/(µM·s) is it times the copies per µM of a compartment (docs/medyan.md, "Binding
  // rates": counting ordered pairs, twice as many, was measured and rejected).
  const double on_rate = b.on * per_uM_;
  toml_ << "\n[[" << table << "]]\nspecies = " << quoted(b.species) << "\nmin_distance = " << num(b.rmin)
        << "\nmax_distance = " << num(b.rmax) << "\non_rate = " << num(on_rate) << "\noff_rate = " << num(b.off)
        << "\nsite_spacing = " << spacing_ << "\n";
  done(b.where, fmt::format("{} {}: ONRATE {} /s per copy and site pair x {:.4g} copies/µM -> {}.{}.on_rate = {:.4g} "
                            "/(µM·s) per pair; off_rate = {} /s; range {}-{} nm",
                            reaction, b.species, b.on, per_uM_, table, i, on_rate, b.off, b.rmin, b.rmax));
}

void Translator::linkers() {
  for (std::size_t i = 0; i < linkers_.size(); ++i) {
    const Binder& b = linkers_[i];
    openBinder("linker", "LINKERREACTION", b, i);
    if (const auto k = listValue("LSTRETCHINGK", i)) {
      toml_ << "stiffness = " << num(*k) << "\n";
      done(whereOf("LSTRETCHINGK"), fmt::format("LSTRETCHINGK -> linker.{}.stiffness = {} pN/nm", i, *k));
    }
    std::string type = "SLIP";
    if (const Entry* e = find("DLUNBINDINGTYPE"); e && i < e->values.size()) type = upperCase(e->values[i]);
    if (type == "SLIP") {
      if (const auto x = listValue("DLUNBINDINGLEN", i)) {
        toml_ << "slip_length = " << num(*x) << "\n";
        done(whereOf("DLUNBINDINGLEN"), fmt::format("DLUNBINDINGTYPE SLIP, DLUNBINDINGLEN -> linker.{}.slip_length = {} nm", i, *x));
      }
    } else {
      skip(whereOf("DLUNBINDINGTYPE"), fmt::format("DLUNBINDINGTYPE {}: cortex's linkers have a slip bond only", type));
    }
  }
  find("DLUNBINDINGAMP");
}

void Translator::motors() {
  for (std::size_t i = 0; i < motors_.size(); ++i) {
    const Binder& b = motors_[i];
    openBinder("motor", "MOTORREACTION", b, i);
    if (!b.walks) skip(b.where, fmt::format("motor {}: no MOTORWALKINGREACTION: walk_rate = 0", b.species));
    if (const auto k = listValue("MSTRETCHINGK", i)) {
      toml_ << "stiffness = " << num(*k) << "\n";
      done(whereOf("MSTRETCHINGK"), fmt::format("MSTRETCHINGK -> motor.{}.stiffness = {} pN/nm", i, *k));
    }
    // MEDYAN's walking reaction moves a motor end from binding site N to N + 1 (the
    // manual's MOTORWALKINGREACTION); its rate is that of one head step of MOTORSTEPSIZE,
    // so the end's mean speed is rate x MOTORSTEPSIZE. cortex's motors walk on a lattice
    // of step_size: the binding sites here, at rate x MOTORSTEPSIZE / site distance.
    const double site_nm = spacing_ * monomer_size_;
    const double head_step = value("MOTORSTEPSIZE").value_or(6.0);
    const double walk = b.walks ? b.walk * head_step / site_nm : 0.0;
    toml_ << "step_size = " << num(site_nm) << "\nwalk_rate = " << num(walk) << "\n";
    if (b.walks)
      done(b.where, fmt::format("MOTORWALKINGREACTION (site N -> N + 1) {} /s per end, MOTORSTEPSIZE {} nm -> "
                                "motor.{}.step_size = {} nm (the binding-site spacing), walk_rate = {} x {} / {} = {:.4g} "
                                "/s (same mean speed)",
                                b.walk, head_step, i, site_nm, b.walk, head_step, site_nm, walk));
    std::string utype = "LOWDUTYCATCH";
    if (const Entry* e = find("DMUNBINDINGTYPE"); e && i < e->values.size()) utype = upperCase(e->values[i]);
    if (const auto f = listValue("DMUNBINDINGFORCE", i)) {
      if (utype == "LOWDUTYCATCH") {
        toml_ << "catch_force = " << num(*f) << "\n";
        done(whereOf("DMUNBINDINGFORCE"), fmt::format("DMUNBINDINGTYPE LOWDUTYCATCH, DMUNBINDINGFORCE -> "
                                                      "motor.{}.catch_force = {} pN",
                                                      i, *f));
      } else {
        skip(whereOf("DMUNBINDINGTYPE"), fmt::format("DMUNBINDINGTYPE {}: cortex's motors have the catch bond "
                                                     "(LOWDUTYCATCH) only",
                                                     utype));
      }
    }
    std::string wtype = "LOWDUTYSTALL";
    if (const Entry* e = find("DMWALKINGTYPE"); e && i < e->values.size()) wtype = upperCase(e->values[i]);
    if (const auto f = listValue("DMWALKINGFORCE", i)) {
      if (wtype == "LOWDUTYSTALL") {
        toml_ << "stall_force = " << num(*f) << "\n";
        done(whereOf("DMWALKINGFORCE"), fmt::format("DMWALKINGTYPE LOWDUTYSTALL, DMWALKINGFORCE -> "
                                                    "motor.{}.stall_force = {} pN",
                                                    i, *f));
      } else {
        skip(whereOf("DMWALKINGTYPE"), fmt::format("DMWALKINGTYPE {}: cortex's walking follows the Hill stall law", wtype));
      }
    }
    const auto hmin = listValue("NUMMOTORHEADSMIN", i), hmax = listValue("NUMMOTORHEADSMAX", i);
    if (hmin && hmax && *hmin >= 1 && *hmax >= *hmin) {
      toml_ << "heads_min = " << static_cast<long long>(*hmin) << "\nheads_max = " << static_cast<long long>(*hmax)
           << "\nhead_binding_rate = " << num(b.walks ? b.walk : 0.2) << "\n";
      done(whereOf("NUMMOTORHEADSMIN"),
           fmt::format("NUMMOTORHEADSMIN/MAX -> motor.{}.heads_min = {}, heads_max = {}; head_binding_rate = the walking "
                       "rate {} /s; off_rate is then one head's unbinding rate (parallel cluster model, docs/medyan.md)",
                       i, *hmin, *hmax, b.walks ? b.walk : 0.2));
    } else if (hmin || hmax) {
      skip(whereOf(hmin ? "NUMMOTORHEADSMIN" : "NUMMOTORHEADSMAX"),
           "NUMMOTORHEADSMIN/MAX: need both, 1 <= MIN <= MAX; motors without a head count written");
    }
  }
  for (const char* k : {"MSTRETCHINGTYPE", "MSTRETCHINGFFTYPE", "LSTRETCHINGTYPE", "LSTRETCHINGFFTYPE"})
    if (const auto w = word(k); w && upperCase(*w) != "HARMONIC")
      skip(whereOf(k), fmt::format("{} {}: cortex's linker and motor springs are harmonic", k, *w));
}

void Translator::branchers() {
  if (n_branchers_ > 0) {
    std::string text = branchers_.str();
    if (const auto th = value("BRBENDINGTHETA")) {
      const double deg = *th * 180.0 / M_PI;
      text += "angle = " + num(deg) + "\n";
      done(whereOf("BRBENDINGTHETA"), fmt::format("BRBENDINGTHETA {} rad -> brancher.angle = {:.4g} degrees", *th, deg));
    }
    text += "site_spacing = " + std::to_string(spacing_) + "\n";
    toml_ << text;
    for (const char* k : {"BRSTRETCHINGK", "BRBENDINGK", "BRDIHEDRALK", "BRPOSITIONK"})
      if (find(k))
        skip(whereOf(k), fmt::format("{}: cortex's branch joint is a position spring and an angle term of its own form "
                                     "(defaults kept)",
                                     k));
  }
  for (const char* k : {"BRSTRETCHINGFFTYPE", "BRSTRETCHINGTYPE", "BRSTRETCHINGL", "BRBENDINGFFTYPE", "BRBENDINGTYPE",
                        "BRDIHEDRALFFTYPE", "BRPOSITIONFFTYPE", "BRPOSITIONTYPE", "BRSTRETCHINGK", "BRBENDINGK",
                        "BRDIHEDRALK", "BRPOSITIONK", "BRBENDINGTHETA"})
    find(k);
}

void Translator::everythingElse() {
  for (const char* k : {"CHEMISTRYFILE", "DISSIPATIONTRACKING", "EVENTTRACKING", "LSTRETCHINGTYPE", "MSTRETCHINGTYPE",
                        "LSTRETCHINGFFTYPE", "MSTRETCHINGFFTYPE", "DMUNBINDINGTYPE", "DMWALKINGTYPE", "DLUNBINDINGTYPE",
                        "VOLUMEFFTYPE", "VOLUMEK", "VOLUMECUTOFF", "FBENDINGTYPE", "FBENDINGFFTYPE", "FSTRETCHINGTYPE",
                        "FSTRETCHINGFFTYPE", "NUMMOTORHEADSMIN", "NUMMOTORHEADSMAX", "MOTORSTEPSIZE", "LSTRETCHINGK",
                        "MSTRETCHINGK", "DLUNBINDINGLEN", "DMUNBINDINGFORCE", "DMWALKINGFORCE", "NUMFILAMENTS",
                        "FILAMENTLENGTH", "FILAMENTTYPE", "PROJECTIONTYPE", "BOUNDARYINTERACTIONK",
                        "BOUNDARYSCREENLENGTH", "BOUNDARYCUTOFF", "BOUNDARYFFTYPE", "MONOMERSIZE", "CYLINDERSIZE",
                        "FSTRETCHINGK", "FBENDINGK", "FBENDINGTHETA", "NUMBINDINGSITES"})
    find(k);
  for (const char* k : {"DISSIPATIONTRACKING", "EVENTTRACKING"})
    if (const auto w = word(k); w && upperCase(*w) == "ON") skip(whereOf(k), fmt::format("{} ON: not available", k));
  for (const auto* list : {&system_, &chemistry_})
    for (const Entry& e : *list)
      if (!used_.count(&e) && !e.values.empty())
        skip(e.where, fmt::format("{}: {}", e.key,
                                  e.nested ? "grouped settings (membranes, MTOCs, ...) are not supported"
                                           : "not supported by cortex"));
}

}  // namespace

MedyanImport importMedyan(const fs::path& system_file, const std::optional<fs::path>& chemistry_file) {
  std::vector<Entry> system = parseFile(system_file);
  fs::path chem = chemistry_file.value_or(fs::path());
  if (!chemistry_file) {
    for (const Entry& e : system)
      if (e.upper == "CHEMISTRYFILE" && !e.values.empty()) chem = system_file.parent_path() / e.values.front();
    if (chem.empty())
      throw InputError(fmt::format("{}: no CHEMISTRYFILE: give the chemistry file as the second argument",
                                   system_file.string()));
  }
  std::vector<Entry> chemistry = parseFile(chem);
  Translator t(std::move(system), std::move(chemistry));
  return t.run(system_file.filename().string(), chem.filename().string());
}

int runImportMedyan(const fs::path& system_file, const std::optional<fs::path>& chemistry_file, const fs::path& output,
                    bool overwrite, bool quiet) {
  const MedyanImport result = importMedyan(system_file, chemistry_file);
  if (fs::exists(output) && !overwrite)
    throw InputError(fmt::format("{}: exists (give --overwrite to replace it)", output.string()));
  writeFileAtomically(output, result.toml);
  if (!quiet) {
    std::cout << "Translated (" << result.translated.size() << "):\n";
    for (const auto& t : result.translated) std::cout << "  " << t << '\n';
  }
  std::cout << "Not translated (" << result.untranslated.size() << "):\n";
  for (const auto& u : result.untranslated) std::cout << "  " << u << '\n';
  std::cout << "Wrote " << output.string() << '\n';
  return 0;
}

}  // namespace cortex
