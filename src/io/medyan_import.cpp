#include "io/medyan_import.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/config.hpp"
#include "io/medyan_translator.hpp"

namespace cortex {
namespace medyan {

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
  for (const char* k : {"RUNTIME", "MINIMIZATIONTIME", "SNAPSHOTTIME"})
    if (const auto t = value(k); t && !(*t > 0))
      throw InputError(fmt::format("{}: {} {}: must be > 0 s", whereOf(k), k, *t));
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
    // Kept as given, so the run is MEDYAN's; but near 1 pN a soft network is not relaxed
    // and what binds depends on the value (docs/medyan.md): say so where users look.
    toml_ << "force_tolerance = " << num(*g)
          << "  # pN on each bead's force; results of soft networks depend on it (docs/medyan.md)\n";
    done(whereOf("GRADIENTTOLERANCE"),
         fmt::format("GRADIENTTOLERANCE -> mechanics.force_tolerance = {} pN, a bound on each bead's force vector "
                     "(what a soft network binds depends on it; docs/medyan.md)",
                     *g));
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

}  // namespace medyan

namespace fs = std::filesystem;
using medyan::Entry;
using medyan::parseFile;
using medyan::Translator;

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
  MedyanImport result = t.run(system_file.filename().string(), chem.filename().string());
  // What is written must be a config cortex runs: a MEDYAN input whose values no
  // keyword check above catches (100 million compartments, no species) is refused here,
  // instead of a file that `cortex check` then refuses naming its own lines.
  try {
    parseConfig(result.toml, "the translated config", system_file.parent_path(), {});
  } catch (const InputError& e) {
    throw InputError(fmt::format("{} and {}: they translate to a config cortex cannot run ({}); nothing was written",
                                 system_file.string(), chem.string(), e.what()));
  }
  return result;
}

int runImportMedyan(const fs::path& system_file, const std::optional<fs::path>& chemistry_file, const fs::path& output,
                    bool overwrite, bool quiet) {
  const MedyanImport result = importMedyan(system_file, chemistry_file);
  if (fs::exists(output) && !overwrite)
    throw InputError(fmt::format("{}: exists (give --overwrite to replace it)", output.string()));
  try {
    writeFileAtomically(output, result.toml);
  } catch (const std::exception& e) {
    // A folder that does not exist, a folder in the way: the command line's doing.
    throw InputError(fmt::format("{}: cannot write the config there: {}", output.string(), e.what()));
  }
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
