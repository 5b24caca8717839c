#include "sweep/sweep_spec.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace cortex {
namespace {

// Largest sweep: a typo in a grid (an extra zero in a list length) should be an error,
// not a million processes.
constexpr std::size_t kMaxMembers = 1'000'000;
// Seeds are stored in the float64 table of sweep.h5: above 2^53 they would lose digits.
constexpr std::int64_t kMaxSeed = std::int64_t{1} << 53;

class SweepFileError {
 public:
  explicit SweepFileError(std::string file) : file_(std::move(file)) {}
  [[noreturn]] void operator()(const toml::node* at, const std::string& key, const std::string& problem) const {
    const std::string where =
        at && at->source().begin.line > 0 ? fmt::format("{}:{}", file_, at->source().begin.line) : file_;
    throw InputError(fmt::format("{}: {}: {}", where, key, problem));
  }

 private:
  std::string file_;
};

// The leaves of a table of settings with their dotted paths, in the order written: a key
// may be given quoted ("membrane.0.radius" = ...) or as nested TOML tables.
struct Setting {
  std::string key;
  const toml::node* value;
};

void collectSettings(const toml::table& table, const std::string& prefix, std::vector<Setting>& out) {
  for (const auto& [name, node] : table) {
    const std::string key = prefix.empty() ? std::string(name.str()) : prefix + "." + std::string(name.str());
    if (const toml::table* nested = node.as_table())
      collectSettings(*nested, key, out);
    else
      out.push_back({key, &node});
  }
}

std::vector<Setting> settingsInOrder(const toml::table& table) {
  std::vector<Setting> settings;
  collectSettings(table, "", settings);
  std::stable_sort(settings.begin(), settings.end(), [](const Setting& a, const Setting& b) {
    const auto &pa = a.value->source().begin, &pb = b.value->source().begin;
    return pa.line != pb.line ? pa.line < pb.line : pa.column < pb.column;
  });
  return settings;
}

// A number in TOML text that parses back to the same double and stays a float
// (10.0, not 10, which TOML would read as an integer).
std::string tomlFloat(double v) {
  std::string text = fmt::format("{}", v);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";  // 'n': inf, nan
  return text;
}

SweptValue sweptValue(const toml::node& node, const std::string& key, const SweepFileError& fail) {
  SweptValue v;
  if (const auto* i = node.as_integer()) {
    v.toml = fmt::format("{}", i->get());
    v.number = static_cast<double>(i->get());
  } else if (const auto* f = node.as_floating_point()) {
    v.toml = tomlFloat(f->get());
    v.number = f->get();
  } else if (const auto* b = node.as_boolean()) {
    v.toml = b->get() ? "true" : "false";
    v.number = b->get() ? 1.0 : 0.0;
  } else if (const auto* s = node.as_string()) {
    std::ostringstream quoted;
    quoted << *s;  // toml++ writes a TOML string with its escapes
    v.toml = quoted.str();
    v.text = s->get();
  } else if (const auto* list = node.as_array()) {
    // A vector such as a direction: passed on as written, recorded as its TOML text.
    if (list->empty()) fail(&node, key, "an array value needs at least one number");
    v.toml = "[";
    for (const toml::node& item : *list) {
      if (!item.is_integer() && !item.is_floating_point())
        fail(&item, key, "an array value holds numbers only, e.g. [0.5, 0.0, 0.866]");
      v.toml += (v.toml.size() > 1 ? ", " : "") + sweptValue(item, key, fail).toml;
    }
    v.toml += "]";
    v.text = v.toml;
  } else {
    fail(&node, key, "must be a number, a boolean, a string or an array of numbers");
  }
  return v;
}

// What makes two swept values the same value (1 and 1.0 are one).
std::string identity(const SweptValue& v) { return v.number ? fmt::format("{}", *v.number) : v.text; }

// Validates a key path as `--set` reads it: dot-separated, no empty part.
void checkKeyPath(const Setting& s, const SweepFileError& fail) {
  if (s.key.empty() || s.key.front() == '.' || s.key.back() == '.' || s.key.find("..") != std::string::npos)
    fail(s.value, fmt::format("\"{}\"", s.key), "is not a key path (parts separated by single dots)");
  for (const char c : s.key)
    if (static_cast<unsigned char>(c) < 0x20 || c == '=' || c == ',')
      fail(s.value, fmt::format("\"{}\"", s.key), "a key path holds no control character, '=' or ','");
}

// Index of `key` in spec.keys, appending it (with its kind) the first time.
std::size_t keyIndex(SweepSpec& spec, const Setting& s, bool is_string, bool seeds_given,
                     const SweepFileError& fail) {
  const auto it = std::find(spec.keys.begin(), spec.keys.end(), s.key);
  if (it == spec.keys.end()) {
    checkKeyPath(s, fail);
    if (s.key == "simulation.seed" && seeds_given) fail(s.value, s.key, "is set by `seeds`; give the seeds there only");
    spec.keys.push_back(s.key);
    spec.key_is_string.push_back(is_string);
    return spec.keys.size() - 1;
  }
  const std::size_t k = static_cast<std::size_t>(it - spec.keys.begin());
  if (spec.key_is_string[k] != is_string)
    fail(s.value, s.key, "mixes strings with numbers or booleans; give one kind of value per key");
  return k;
}

std::vector<std::optional<std::int64_t>> readSeeds(const toml::table& root, const SweepFileError& fail) {
  const toml::node* node = root.get("seeds");
  if (!node) return {std::nullopt};
  std::vector<std::optional<std::int64_t>> seeds;
  if (const auto* n = node->as_integer()) {
    if (n->get() < 1 || n->get() > 100000) fail(node, "seeds", fmt::format("must be in [1, 100000], got {}", n->get()));
    for (std::int64_t s = 1; s <= n->get(); ++s) seeds.emplace_back(s);
    return seeds;
  }
  const toml::array* list = node->as_array();
  if (!list || list->empty())
    fail(node, "seeds", "must be a number of seeds (1..N) or a non-empty list of seeds, e.g. [1, 7, 9]");
  std::set<std::int64_t> seen;
  for (const toml::node& item : *list) {
    const auto* s = item.as_integer();
    if (!s || s->get() < 0 || s->get() > kMaxSeed)
      fail(&item, "seeds", fmt::format("every seed must be an integer in [0, {}]", kMaxSeed));
    if (!seen.insert(s->get()).second) fail(&item, "seeds", fmt::format("seed {} is listed twice", s->get()));
    seeds.emplace_back(s->get());
  }
  return seeds;
}

// Full factorial product of the [grid] lists; the last key varies fastest.
using Points = std::vector<std::vector<std::optional<SweptValue>>>;

Points gridPoints(SweepSpec& spec, const toml::table& grid, bool seeds_given, const SweepFileError& fail) {
  std::vector<std::vector<SweptValue>> axes;
  std::set<std::string> keys;
  for (const Setting& s : settingsInOrder(grid)) {
    // "membrane.0.x" = [...] beside [grid.membrane.0] x = [...] names one key twice; the
    // later one was dropped without a word.
    if (!keys.insert(s.key).second) fail(s.value, "grid." + s.key, "is given twice");
    const toml::array* list = s.value->as_array();
    if (!list || list->empty())
      fail(s.value, "grid." + s.key, "must be a non-empty list of values, e.g. [10.0, 20.0]");
    std::vector<SweptValue> axis;
    std::set<std::string> seen;  // by value: 1 and 1.0 are one value
    for (const toml::node& item : *list) {
      axis.push_back(sweptValue(item, "grid." + s.key, fail));
      const SweptValue& v = axis.back();
      if (!seen.insert(identity(v)).second)
        fail(&item, "grid." + s.key,
             fmt::format("lists {} twice: the members would be the same run (replicates are `seeds`)", v.toml));
    }
    const bool is_string = !axis.front().number;
    for (const SweptValue& v : axis)
      if (!v.number != is_string) fail(s.value, "grid." + s.key, "mixes strings with numbers or booleans");
    keyIndex(spec, s, is_string, seeds_given, fail);
    axes.push_back(std::move(axis));
  }
  std::size_t count = 1;
  for (const auto& axis : axes) {
    count *= axis.size();
    if (count > kMaxMembers) fail(&grid, "grid", fmt::format("spans more than {} points", kMaxMembers));
  }
  Points points(count);
  for (std::size_t p = 0; p < count; ++p) {
    std::size_t rest = p;
    points[p].resize(axes.size());
    for (std::size_t k = axes.size(); k-- > 0;) {
      points[p][k] = axes[k][rest % axes[k].size()];
      rest /= axes[k].size();
    }
  }
  return points;
}

Points listedPoints(SweepSpec& spec, const toml::array& list, bool seeds_given, const SweepFileError& fail) {
  if (list.empty() || !list.is_array_of_tables())
    fail(&list, "members", "must be a non-empty list of tables ([[members]]), one per member");
  if (list.size() > kMaxMembers) fail(&list, "members", fmt::format("lists more than {} members", kMaxMembers));
  std::vector<std::vector<std::pair<std::size_t, SweptValue>>> entries;
  for (std::size_t m = 0; m < list.size(); ++m) {
    entries.emplace_back();
    for (const Setting& s : settingsInOrder(*list[m].as_table())) {
      const std::string name = fmt::format("members.{}.{}", m, s.key);
      SweptValue v = sweptValue(*s.value, name, fail);
      const std::size_t k = keyIndex(spec, s, !v.number, seeds_given, fail);
      entries.back().emplace_back(k, std::move(v));
    }
  }
  // Keys are all known only now: a member leaving a key out gets an empty value.
  Points points;
  std::set<std::string> seen;
  for (std::size_t m = 0; m < entries.size(); ++m) {
    points.emplace_back(spec.keys.size());
    for (auto& [k, v] : entries[m]) points.back()[k] = std::move(v);
    std::string same;
    for (const auto& v : points.back()) same += (v ? identity(*v) : "\x01absent") + '\x02';
    if (!seen.insert(same).second)
      fail(&list[m], fmt::format("members.{}", m),
           "sets what an earlier member sets: the two would be the same run (replicates are `seeds`)");
  }
  return points;
}

}  // namespace

SweepSpec readSweepFile(const std::filesystem::path& file) {
  SweepSpec spec;
  spec.file = file;
  spec.text = readWholeFile(file, 1 << 20);
  const SweepFileError fail(file.string());
  toml::table root;
  try {
    root = toml::parse(spec.text, file.string());
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}: invalid TOML: {}", file.string(), e.source().begin.line, e.description()));
  }
  for (const auto& [key, node] : root)
    if (key != "base" && key != "seeds" && key != "parallel" && key != "grid" && key != "members")
      fail(&node, std::string(key.str()), "unknown key (a sweep file has base, seeds, parallel, [grid] or [[members]])");

  const toml::node* base = root.get("base");
  if (!base || !base->is_string() || base->as_string()->get().empty())
    fail(base ? base : &root, "base",
         "is required: the path of the run config to sweep over (a string), relative to this file");
  spec.base = (file.parent_path() / base->as_string()->get()).lexically_normal();

  if (const toml::node* parallel = root.get("parallel")) {
    const auto* n = parallel->as_integer();
    if (!n || n->get() < 1 || n->get() > 4096) fail(parallel, "parallel", "must be an integer in [1, 4096]");
    spec.parallel = static_cast<int>(n->get());
  }

  const auto seeds = readSeeds(root, fail);
  const bool seeds_given = root.contains("seeds");
  const toml::node* grid = root.get("grid");
  const toml::node* listed = root.get("members");
  if (grid && listed) fail(listed, "members", "give either [grid] or [[members]], not both");
  if (grid && !grid->is_table()) fail(grid, "grid", "must be a table of key = [values]");
  if (listed && !listed->is_array()) fail(listed, "members", "must be a list of tables ([[members]])");
  if (!grid && !listed && !seeds_given)
    fail(&root, "grid", "nothing to sweep: give [grid], [[members]] or seeds");
  const Points points = grid     ? gridPoints(spec, *grid->as_table(), seeds_given, fail)
                        : listed ? listedPoints(spec, *listed->as_array(), seeds_given, fail)
                                 : Points(1);
  if (points.size() * seeds.size() > kMaxMembers)
    fail(&root, "seeds", fmt::format("the sweep would have more than {} members", kMaxMembers));

  for (const auto& point : points)
    for (const auto& seed : seeds) spec.members.push_back({spec.members.size(), point, seed});
  return spec;
}

bool isSweepFile(const std::filesystem::path& file) {
  try {
    return toml::parse(readWholeFile(file, 1 << 20), file.string()).contains("base");
  } catch (const std::exception&) {
    return false;
  }
}

std::vector<std::string> memberOverrides(const SweepSpec& spec, const SweepMember& member) {
  std::vector<std::string> overrides;
  for (std::size_t k = 0; k < spec.keys.size(); ++k)
    if (member.values[k]) overrides.push_back(spec.keys[k] + "=" + member.values[k]->toml);
  if (member.seed) overrides.push_back(fmt::format("simulation.seed={}", *member.seed));
  return overrides;
}

std::filesystem::path memberFolder(const SweepSpec& spec, std::size_t index) {
  const std::size_t width = std::max<std::size_t>(4, fmt::format("{}", spec.members.size() - 1).size());
  return std::filesystem::path("members") / fmt::format("{:0{}}", index, width);
}

}  // namespace cortex
