// Translator (io/medyan_translator.hpp): the filament type, linkers, motors and branchers.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "io/medyan_translator.hpp"

namespace cortex::medyan {

void Translator::filamentType() {
  const bool filaments = species_.end() != std::find_if(species_.begin(), species_.end(),
                                                       [](const auto& s) { return s.second.kind == "FILAMENT"; });
  monomer_size_ = value("MONOMERSIZE").value_or(2.7);
  cylinder_size_ = value("CYLINDERSIZE").value_or(108.0);
  for (const auto& [key, size] : {std::pair{"MONOMERSIZE", monomer_size_}, std::pair{"CYLINDERSIZE", cylinder_size_}})
    if (!(size > 0)) throw InputError(fmt::format("{}: {} {}: must be > 0 nm", whereOf(key), key, size));
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
      toml_ << "\n[[filaments]]\ntype = \"actin\"\ncount = " << count(*n, whereOf("NUMFILAMENTS"), "NUMFILAMENTS")
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

void Translator::bindingSites() {
  if (const auto n = value("NUMBINDINGSITES")) {
    // 0 became a site on every monomer (cylinder/0 rounded to the largest int, clamped).
    if (!(*n >= 1) || *n > cylinder_monomers_)
      throw InputError(fmt::format("{}: NUMBINDINGSITES {}: a cylinder of {} monomers holds 1 to {} binding sites",
                                   whereOf("NUMBINDINGSITES"), *n, cylinder_monomers_, cylinder_monomers_));
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
    motorForce(i, "DMUNBINDINGTYPE", "LOWDUTYCATCH", "DMUNBINDINGFORCE", "catch_force",
               "cortex's motors have the catch bond (LOWDUTYCATCH) only");
    motorForce(i, "DMWALKINGTYPE", "LOWDUTYSTALL", "DMWALKINGFORCE", "stall_force",
               "cortex's walking follows the Hill stall law");
    const auto hmin = listValue("NUMMOTORHEADSMIN", i), hmax = listValue("NUMMOTORHEADSMAX", i);
    if (hmin && hmax && *hmin >= 1 && *hmax >= *hmin) {
      toml_ << "heads_min = " << count(*hmin, whereOf("NUMMOTORHEADSMIN"), "NUMMOTORHEADSMIN")
            << "\nheads_max = " << count(*hmax, whereOf("NUMMOTORHEADSMAX"), "NUMMOTORHEADSMAX")
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

void Translator::motorForce(std::size_t i, const char* type_key, const char* supported, const char* force_key,
                            const char* toml_key, const char* unsupported) {
  std::string type = supported;
  if (const Entry* e = find(type_key); e && i < e->values.size()) type = upperCase(e->values[i]);
  const auto f = listValue(force_key, i);
  if (!f) return;
  if (type != supported) {
    skip(whereOf(type_key), fmt::format("{} {}: {}", type_key, type, unsupported));
    return;
  }
  toml_ << toml_key << " = " << num(*f) << "\n";
  done(whereOf(force_key), fmt::format("{} {}, {} -> motor.{}.{} = {} pN", type_key, supported, force_key, i, toml_key, *f));
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

}  // namespace cortex::medyan
