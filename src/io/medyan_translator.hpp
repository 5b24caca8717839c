// Translating MEDYAN input files into a cortex config (`cortex import-medyan`,
// medyan_import.hpp): one Translator, the config written section by section, its
// methods in three files by what they translate: run control, geometry and boundary
// (medyan_import.cpp), the chemistry file's species and reactions (medyan_chemistry.cpp),
// filaments, linkers, motors and branchers (medyan_filaments.cpp). Internal to io/.
#pragma once

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/medyan_import.hpp"
#include "io/medyan_input.hpp"

namespace cortex::medyan {

inline constexpr double kCopiesPerMicromolarFemtolitre = 602.214076;  // N_A · 1 µM · 1 fL

// A number as TOML: always a float literal.
std::string num(double x);
std::string quoted(const std::string& s);

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
  // A motor's force law: `type_key` names it per motor type (default `supported`, the
  // one cortex has); then `force_key`'s entry i becomes motor.i.`toml_key` (pN), and
  // another type is listed untranslated with `unsupported` as the reason.
  void motorForce(std::size_t i, const char* type_key, const char* supported, const char* force_key,
                  const char* toml_key, const char* unsupported);
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
  // A count (filaments, copies, heads) as written: a whole number a copy number can hold.
  // 1e300 was written as -9223372036854775808, and 2.5 as 2.
  static long long count(double v, const std::string& where, const std::string& key) {
    if (!(v >= 0 && v <= 2e9 && v == std::floor(v)))
      throw InputError(fmt::format("{}: {} must be a whole number from 0 to 2e9, got {:g}", where, key, v));
    return static_cast<long long>(v);
  }
  // Where the entry find() reads is: the last non-empty one.
  std::string whereOf(const std::string& upper) {
    std::string where;
    for (const Entry& e : system_)
      if (e.upper == upper && !e.values.empty()) where = e.where;
    return where;
  }
  void done(const std::string& where, const std::string& what) { out_.translated.push_back(where + ": " + what); }
  void skip(const std::string& where, const std::string& what) { out_.untranslated.push_back(where + ": " + what); }
};

}  // namespace cortex::medyan
