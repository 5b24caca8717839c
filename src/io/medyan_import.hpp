// `cortex import-medyan`: translates MEDYAN input files (a system file and its chemistry
// file, in the format of MEDYAN's public manual, docs/manual/input-files.md) into a
// cortex config, with unit conversions, and lists what it could not translate.
// The mapping, keyword by keyword, is in docs/medyan.md.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cortex {

struct MedyanImport {
  std::string toml;                       // the cortex config
  std::vector<std::string> translated;    // "file:line: KEY -> cortex.key (conversion)"
  std::vector<std::string> untranslated;  // "file:line: KEY: why", nothing of it is in the config
};

// Reads the system file and the chemistry file (by default the system file's CHEMISTRYFILE,
// relative to the system file's folder). Throws InputError naming file and line when a file
// cannot be read or is not valid MEDYAN input (unbalanced parentheses, a number that is not
// one, a reaction that does not follow the manual's form, missing geometry).
MedyanImport importMedyan(const std::filesystem::path& system_file,
                          const std::optional<std::filesystem::path>& chemistry_file);

// The subcommand: writes the config to `output` (refusing to replace an existing file
// unless `overwrite`), prints what was translated and what was not. Returns the exit code:
// 0 when the config was written, 2 (InputError) otherwise.
int runImportMedyan(const std::filesystem::path& system_file,
                    const std::optional<std::filesystem::path>& chemistry_file,
                    const std::filesystem::path& output, bool overwrite, bool quiet);

}  // namespace cortex
