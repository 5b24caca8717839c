#include "filament/filament_network.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cortex {

FilamentNetwork::FilamentNetwork(FilamentConfig config) : config_(std::move(config)) {}

Index FilamentNetwork::addFilament(Filament f) {
  if (f.beads.size() < 2 || f.beads.size() != f.lattice.size())
    throw std::invalid_argument("filament needs at least two beads, one lattice coordinate each");
  filaments_.push_back(std::move(f));
  return static_cast<Index>(filaments_.size()) - 1;
}

int FilamentNetwork::spacing(BinderKind kind, Index type) const {
  switch (kind) {
    case BinderKind::kLinker:
      return config_.linkers[type].site_spacing;
    case BinderKind::kMotor: {
      const MotorType& m = config_.motors[type];
      // Motors step from site to site: their lattice is their step, in whole monomers of
      // the filaments they walk on (all types share the first type's monomer size).
      return std::max(1, m.stepMonomers(config_.types.front().monomer_size));
    }
    case BinderKind::kBrancher:
      return config_.branchers[type].site_spacing;
  }
  return 1;
}

std::pair<std::int64_t, std::int64_t> FilamentNetwork::sitesOnCylinder(BinderKind kind, Index type, Index f,
                                                                       Index c) const {
  const Filament& fil = filaments_[f];
  const double sp = spacing(kind, type);
  const double lo = static_cast<double>(fil.lattice[c]), hi = static_cast<double>(fil.lattice[c + 1]);
  // Sites with lo <= (j + 1/2) sp < hi; the last cylinder also owns a site exactly at its end.
  const auto first = static_cast<std::int64_t>(std::ceil(lo / sp - 0.5));
  auto last = static_cast<std::int64_t>(std::ceil(hi / sp - 0.5)) - 1;
  if (c == fil.numCylinders() - 1 && (static_cast<double>(last + 1) + 0.5) * sp == hi) ++last;
  return {first, last};
}

void FilamentNetwork::grow(Index f, bool plus_end) {
  Filament& fil = filaments_[f];
  const FilamentType& t = type(fil.type);
  const std::size_t n = fil.beads.size();
  if (plus_end) {
    const Vec3 step = t.monomer_size * fil.plusDirection();
    if (fil.lattice[n - 1] - fil.lattice[n - 2] >= t.cylinder_monomers) {
      fil.beads.push_back(fil.beads.back() + step);
      fil.lattice.push_back(fil.lattice.back() + 1);
    } else {
      fil.beads.back() += step;
      ++fil.lattice.back();
    }
  } else {
    const Vec3 step = t.monomer_size * fil.minusDirection();
    if (fil.lattice[1] - fil.lattice[0] >= t.cylinder_monomers) {
      fil.beads.insert(fil.beads.begin(), fil.beads.front() + step);
      fil.lattice.insert(fil.lattice.begin(), fil.lattice.front() - 1);
    } else {
      fil.beads.front() += step;
      --fil.lattice.front();
    }
  }
}

bool FilamentNetwork::shrink(Index f, bool plus_end, std::vector<Release>& released) {
  Filament& fil = filaments_[f];
  if (fil.monomers() <= minimumMonomers(fil)) return false;
  const FilamentType& t = type(fil.type);
  const std::size_t n = fil.beads.size();
  if (plus_end) {
    if (fil.lattice[n - 1] - fil.lattice[n - 2] == 1) {
      fil.beads.pop_back();
      fil.lattice.pop_back();
    } else {
      fil.beads.back() -= t.monomer_size * fil.plusDirection();
      --fil.lattice.back();
    }
  } else {
    if (fil.lattice[1] - fil.lattice[0] == 1) {
      fil.beads.erase(fil.beads.begin());
      fil.lattice.erase(fil.lattice.begin());
    } else {
      fil.beads.front() -= t.monomer_size * fil.minusDirection();
      ++fil.lattice.front();
    }
  }
  releaseBeyond(f, released);
  return true;
}

// Everything bound to a site filament f no longer covers comes off.
void FilamentNetwork::releaseBeyond(Index f, std::vector<Release>& released) {
  auto sweep = [&](BinderKind kind, std::vector<Binding>& bound, auto species_of) {
    for (std::size_t i = bound.size(); i-- > 0;) {
      const Binding& b = bound[i];
      for (int e = 0; e < 2; ++e) {
        if (b.filament[e] != f || siteExists(kind, b.type, f, b.site[e])) continue;
        released.push_back({species_of(b.type), sitePosition(kind, b.type, b.filament[1 - e], b.site[1 - e])});
        unbind(kind, i);
        break;
      }
    }
  };
  sweep(BinderKind::kLinker, linkers_, [&](Index t) { return config_.linkers[t].species_index; });
  sweep(BinderKind::kMotor, motors_, [&](Index t) { return config_.motors[t].species_index; });
  for (std::size_t i = branches_.size(); i-- > 0;) {
    const Branch& b = branches_[i];
    if (b.mother != f || siteExists(BinderKind::kBrancher, b.type, f, b.site)) continue;
    released.push_back({config_.branchers[b.type].species_index, filaments_[b.daughter].beads.front()});
    unbranch(i);
  }
}

void FilamentNetwork::bind(BinderKind kind, const Binding& b) {
  for (int e = 0; e < 2; ++e) occupied_.insert(key(kind, b.type, b.filament[e], b.site[e]));
  (kind == BinderKind::kMotor ? motors_ : linkers_).push_back(b);
}

void FilamentNetwork::unbind(BinderKind kind, std::size_t index) {
  auto& bound = kind == BinderKind::kMotor ? motors_ : linkers_;
  const Binding& b = bound[index];
  for (int e = 0; e < 2; ++e) occupied_.erase(key(kind, b.type, b.filament[e], b.site[e]));
  bound.erase(bound.begin() + static_cast<std::ptrdiff_t>(index));
}

bool FilamentNetwork::walk(std::size_t index, int end) {
  Binding& m = motors_[index];
  const std::int64_t next = m.site[end] + 1;
  if (!siteExists(BinderKind::kMotor, m.type, m.filament[end], next) ||
      occupied(BinderKind::kMotor, m.type, m.filament[end], next))
    return false;
  occupied_.erase(key(BinderKind::kMotor, m.type, m.filament[end], m.site[end]));
  occupied_.insert(key(BinderKind::kMotor, m.type, m.filament[end], next));
  m.site[end] = next;
  return true;
}

Index FilamentNetwork::branch(Index type, Index mother, std::int64_t site, const Vec3& daughter_direction) {
  const BrancherType& b = config_.branchers[type];
  const FilamentType& t = config_.types[b.filament_type_index];
  Filament daughter = makeStraightFilament(b.filament_type_index, sitePosition(BinderKind::kBrancher, type, mother, site),
                                           daughter_direction, 1, t.cylinder_monomers, t.monomer_size);
  daughter.minus_capped = true;
  const Index d = addFilament(std::move(daughter));
  occupied_.insert(key(BinderKind::kBrancher, type, mother, site));
  branches_.push_back({type, mother, d, site});
  return d;
}

void FilamentNetwork::unbranch(std::size_t index) {
  const Branch& b = branches_[index];
  occupied_.erase(key(BinderKind::kBrancher, b.type, b.mother, b.site));
  filaments_[b.daughter].minus_capped = false;
  branches_.erase(branches_.begin() + static_cast<std::ptrdiff_t>(index));
}

Index FilamentNetwork::numBeads() const {
  Index n = 0;
  for (const Filament& f : filaments_) n += static_cast<Index>(f.beads.size());
  return n;
}

double FilamentNetwork::totalLength() const {
  double length = 0.0;
  for (const Filament& f : filaments_) length += f.length();
  return length;
}

CylinderPoint FilamentNetwork::attachment(BinderKind kind, Index type, Index filament, std::int64_t site) const {
  const auto [c, w] = filaments_[filament].locate(siteCoordinate(kind, type, site));
  return {bead_start_[filament] + c, bead_start_[filament] + c + 1, w};
}

const std::string& FilamentNetwork::name() const {
  static const std::string kName = "filaments";
  return kName;
}

void FilamentNetwork::setOffset(Index offset) {
  Body::setOffset(offset);
  FilamentLayout& l = layout_;
  l.bead_offset = offset;
  l.cylinders.clear();
  l.hinges.clear();
  l.linkers.clear();
  l.motors.clear();
  l.branches.clear();
  bead_start_.resize(filaments_.size());
  Index bead = 0;
  for (std::size_t f = 0; f < filaments_.size(); ++f) {
    const Filament& fil = filaments_[f];
    bead_start_[f] = bead;
    const double delta = type(fil.type).monomer_size;
    for (Index c = 0; c < fil.numCylinders(); ++c) {
      l.cylinders.push_back({bead + c, bead + c + 1, static_cast<Index>(f), fil.type,
                             static_cast<double>(fil.lattice[c + 1] - fil.lattice[c]) * delta});
      if (c > 0) l.hinges.push_back({bead + c - 1, bead + c, bead + c + 1, fil.type});
    }
    bead += static_cast<Index>(fil.beads.size());
  }
  l.num_beads = bead;
  auto springs = [&](BinderKind kind, const std::vector<Binding>& bound, std::vector<Spring>& out, auto stiffness) {
    for (const Binding& b : bound)
      out.push_back({attachment(kind, b.type, b.filament[0], b.site[0]),
                     attachment(kind, b.type, b.filament[1], b.site[1]), stiffness(b.type), b.rest_length});
  };
  springs(BinderKind::kLinker, linkers_, l.linkers, [&](Index t) { return config_.linkers[t].stiffness; });
  springs(BinderKind::kMotor, motors_, l.motors, [&](Index t) { return config_.motors[t].stiffness; });
  for (const Branch& b : branches_) {
    const BrancherType& t = config_.branchers[b.type];
    l.branches.push_back({attachment(BinderKind::kBrancher, b.type, b.mother, b.site), bead_start_[b.daughter],
                          bead_start_[b.daughter] + 1, t.position_stiffness, t.angle_stiffness,
                          std::cos(t.angle * M_PI / 180.0)});
  }
  ++l.version;
}

void FilamentNetwork::moveOffset(Index offset) {
  Body::setOffset(offset);
  layout_.bead_offset = offset;
}

void FilamentNetwork::gather(double* out) const {
  for (const Filament& f : filaments_)
    for (const Vec3& p : f.beads) {
      out[0] = p.x(), out[1] = p.y(), out[2] = p.z();
      out += 3;
    }
}

void FilamentNetwork::frozen(char* mask) const {
  for (const Filament& f : filaments_) {
    std::fill(mask, mask + f.beads.size(), 0);
    mask[0] = f.minus_anchored ? 1 : 0;
    if (f.minus_clamped && f.beads.size() > 1) mask[1] = 1;
    mask += f.beads.size();
  }
}

void FilamentNetwork::scatter(const double* in) {
  for (Filament& f : filaments_)
    for (Vec3& p : f.beads) {
      p = Vec3(in[0], in[1], in[2]);
      in += 3;
    }
}

void FilamentNetwork::restore(std::vector<Filament> filaments, std::vector<Binding> linkers,
                              std::vector<Binding> motors, std::vector<Branch> branches) {
  filaments_ = std::move(filaments);
  linkers_ = std::move(linkers);
  motors_ = std::move(motors);
  branches_ = std::move(branches);
  occupied_.clear();
  for (const Binding& b : linkers_)
    for (int e = 0; e < 2; ++e) occupied_.insert(key(BinderKind::kLinker, b.type, b.filament[e], b.site[e]));
  for (const Binding& b : motors_)
    for (int e = 0; e < 2; ++e) occupied_.insert(key(BinderKind::kMotor, b.type, b.filament[e], b.site[e]));
  for (const Branch& b : branches_) occupied_.insert(key(BinderKind::kBrancher, b.type, b.mother, b.site));
}

}  // namespace cortex
