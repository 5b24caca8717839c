// Reading MEDYAN input files (the format of MEDYAN's public manual, docs/manual/
// input-files.md): statements in any of their three spellings, numbers, and the reaction
// form of the chemistry file. What they mean in cortex is medyan_import.cpp's business.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cortex::medyan {

// One statement of a MEDYAN input file. Three spellings reach the same form:
//   KEY: v1 v2 ...        (the legacy colon form of the example files)
//   KEY v1 v2 ...         (a bare line, e.g. `allow-same-filament-pair-binding false`)
//   (KEY v1 v2 ...)       (the s-expression form of the manual, possibly over lines;
//                          nested groups are flattened and marked)
struct Entry {
  std::string key;    // as written, without a trailing ':'
  std::string upper;  // upper case, for matching
  std::vector<std::string> values;
  std::string where;  // "file:line"
  bool nested = false;
};

std::string upperCase(std::string s);

// Every statement of a file, in order. Throws InputError naming file and line on
// unbalanced parentheses or a parenthesis inside a `KEY: value` line.
std::vector<Entry> parseFile(const std::filesystem::path& file);

// The text as a finite number, or nothing.
std::optional<double> toNumber(const std::string& s);
// Value i of a statement as a number; InputError naming file, line and key otherwise.
double number(const Entry& e, std::size_t i, const char* what);

// A species reference NAME:TYPE[:POS] of a reaction.
struct Ref {
  std::string name, type, pos;
};

struct Reaction {
  std::vector<Ref> reactants, products;
  std::vector<double> params;
  bool reversible = false;
  int filament_type = -1;
  bool dissipation = false;
};

// Parses "[DELG:ID] [FILTYPE] A:T + B:T (->|<->) C:T + D:T p1 p2 ..."; InputError naming
// file and line when it does not follow that form.
Reaction parseReaction(const Entry& e, bool has_filament_type);

}  // namespace cortex::medyan
