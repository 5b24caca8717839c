#include "io/filament_checkpoint.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace cortex {
namespace {

constexpr std::int8_t kCapped = 1, kAnchored = 2, kClamped = 4;

void writeBindings(h5::File& f, const std::string& path, const std::vector<Binding>& bound) {
  std::vector<std::int64_t> ids;
  std::vector<double> rest;
  for (const Binding& b : bound) {
    ids.insert(ids.end(), {b.type, b.filament[0], b.filament[1], b.site[0], b.site[1]});
    rest.push_back(b.rest_length);
  }
  f.write(path + "/ids", ids, {bound.size(), 5});
  f.write(path + "/rest_length", rest);
  std::vector<std::int64_t> heads;
  for (const Binding& b : bound) heads.push_back(b.heads);
  f.write(path + "/heads", heads);
}

std::vector<Binding> readBindings(const h5::File& f, const std::string& path, std::size_t filaments,
                                  const std::string& file_name) {
  const std::vector<std::int64_t> ids = f.readInt64(path + "/ids");
  const std::vector<double> rest = f.readDoubles(path + "/rest_length");
  if (ids.size() != 5 * rest.size()) throw InputError(fmt::format("{}: {} is malformed", file_name, path));
  // Head counts (motors with heads modelled); absent in checkpoints of earlier versions.
  const std::vector<std::int64_t> heads =
      f.exists(path + "/heads") ? f.readInt64(path + "/heads") : std::vector<std::int64_t>{};
  if (!heads.empty() && heads.size() != rest.size())
    throw InputError(fmt::format("{}: {}/heads is malformed", file_name, path));
  std::vector<Binding> out(rest.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::int64_t* r = &ids[5 * i];
    out[i].type = static_cast<Index>(r[0]);
    out[i].filament = {static_cast<Index>(r[1]), static_cast<Index>(r[2])};
    out[i].site = {r[3], r[4]};
    out[i].rest_length = rest[i];
    out[i].heads = heads.empty() ? 0 : static_cast<int>(heads[i]);
    for (Index fil : out[i].filament)
      if (fil < 0 || static_cast<std::size_t>(fil) >= filaments)
        throw InputError(fmt::format("{}: {} refers to a missing filament", file_name, path));
  }
  return out;
}

}  // namespace

void writeFilamentState(h5::File& f, const FilamentState& network) {
  std::vector<double> beads;
  std::vector<std::int64_t> lattice, offsets{0};
  std::vector<std::int32_t> types;
  std::vector<std::int8_t> flags;
  for (const Filament& fil : network.filaments) {
    for (const Vec3& p : fil.beads) beads.insert(beads.end(), {p.x(), p.y(), p.z()});
    lattice.insert(lattice.end(), fil.lattice.begin(), fil.lattice.end());
    offsets.push_back(static_cast<std::int64_t>(lattice.size()));
    types.push_back(fil.type);
    flags.push_back(static_cast<std::int8_t>((fil.minus_capped ? kCapped : 0) | (fil.minus_anchored ? kAnchored : 0) |
                                                (fil.minus_clamped ? kClamped : 0)));
  }
  f.createGroups("/filaments");
  f.write("/filaments/beads", beads, {lattice.size(), 3});
  f.write("/filaments/lattice", lattice);
  f.write("/filaments/offsets", offsets);
  f.write("/filaments/types", types);
  f.write("/filaments/flags", flags);
  writeBindings(f, "/filaments/linkers", network.linkers);
  writeBindings(f, "/filaments/motors", network.motors);
  std::vector<std::int64_t> branches;
  for (const Branch& b : network.branches) branches.insert(branches.end(), {b.type, b.mother, b.daughter, b.site});
  f.write("/filaments/branches", branches, {network.branches.size(), 4});
  const FilamentEvents& e = network.events;
  f.write("/filaments/events", std::vector<std::int64_t>{e.linker_bindings, e.linker_unbindings, e.motor_bindings,
                                                          e.motor_unbindings, e.motor_steps});
}

FilamentState readFilamentState(const h5::File& f, const std::string& file_name) {
  FilamentState s;
  const std::vector<double> beads = f.readDoubles("/filaments/beads");
  const std::vector<std::int64_t> lattice = f.readInt64("/filaments/lattice");
  const std::vector<std::int64_t> offsets = f.readInt64("/filaments/offsets");
  const std::vector<std::int32_t> types = f.readInt32("/filaments/types");
  const std::vector<std::int8_t> flags = f.readInt8("/filaments/flags");
  auto malformed = [&](const char* what) {
    return InputError(fmt::format("{}: /filaments/{} is malformed", file_name, what));
  };
  if (beads.size() != 3 * lattice.size() || offsets.empty() || offsets.front() != 0 ||
      offsets.back() != static_cast<std::int64_t>(lattice.size()) || types.size() + 1 != offsets.size() ||
      flags.size() != types.size())
    throw malformed("beads");
  for (std::size_t i = 0; i < types.size(); ++i) {
    Filament fil;
    fil.type = types[i];
    fil.minus_capped = flags[i] & kCapped;
    fil.minus_anchored = flags[i] & kAnchored;
    fil.minus_clamped = flags[i] & kClamped;
    if (offsets[i + 1] - offsets[i] < 2) throw malformed("offsets");
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      fil.beads.emplace_back(beads[3 * b], beads[3 * b + 1], beads[3 * b + 2]);
      fil.lattice.push_back(lattice[b]);
    }
    s.filaments.push_back(std::move(fil));
  }
  s.linkers = readBindings(f, "/filaments/linkers", s.filaments.size(), file_name);
  s.motors = readBindings(f, "/filaments/motors", s.filaments.size(), file_name);
  if (f.exists("/filaments/events")) {  // absent in checkpoints of earlier versions
    const std::vector<std::int64_t> e = f.readInt64("/filaments/events");
    if (e.size() != 5) throw malformed("events");
    s.events = {e[0], e[1], e[2], e[3], e[4]};
  }
  const std::vector<std::int64_t> branches = f.readInt64("/filaments/branches");
  if (branches.size() % 4 != 0) throw malformed("branches");
  for (std::size_t i = 0; i < branches.size(); i += 4) {
    const Branch b{static_cast<Index>(branches[i]), static_cast<Index>(branches[i + 1]),
                   static_cast<Index>(branches[i + 2]), branches[i + 3]};
    if (b.mother < 0 || b.daughter < 0 || static_cast<std::size_t>(std::max(b.mother, b.daughter)) >= s.filaments.size())
      throw malformed("branches");
    s.branches.push_back(b);
  }
  return s;
}

}  // namespace cortex
