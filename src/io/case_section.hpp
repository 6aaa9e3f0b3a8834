// Reading one table of a case file (case.cpp, case_obstacles.cpp): typed keys with
// their ranges, each key remembered so that the rest can be refused.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <toml++/toml.h>
#include <vector>

#include "io/case_reader.hpp"
#include "mesh/mesh.hpp"  // Point

namespace fsi::case_detail {

// A TOML number as a double. toml++'s value<double>() refuses integers that a double
// cannot hold exactly (found by fuzzing: L = 30000000020000000 threw
// bad_optional_access); the nearest double is what a user means.
inline double as_double(const toml::node& n) {
  if (const auto* i = n.as_integer()) return static_cast<double>(i->get());
  return n.as_floating_point()->get();
}

// Reads one section, remembering which keys it consumed so the rest can be rejected
// (and, for case_keys(), which keys exist).
class Section {
 public:
  Section(const toml::table* table, std::string name, const Origin& origin, std::vector<std::string>* known)
      : table_(table), name_(std::move(name)), origin_(origin), known_(known) {}

  double number(const std::string& key, double value, const Range& range = kAny) {
    const toml::node* n = find(key);
    if (!n) return value;
    if (!n->is_number()) fail(origin_, full(key), "must be a number", range.text());
    const double v = as_double(*n);
    if (!std::isfinite(v)) fail(origin_, full(key), "must be finite", range.text());
    if (!range.contains(v)) fail(origin_, full(key), "= " + shortest(v) + " is out of range", range.text());
    return v;
  }
  int integer(const std::string& key, int value, int lo, int hi) {
    const toml::node* n = find(key);
    if (!n) return value;
    const std::string allowed = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!n->is_integer()) fail(origin_, full(key), "must be an integer", allowed);
    const int64_t v = n->as_integer()->get();
    if (v < lo || v > hi) fail(origin_, full(key), "= " + std::to_string(v) + " is out of range", allowed);
    return static_cast<int>(v);
  }
  std::string text(const std::string& key, std::string value) {
    const toml::node* n = find(key);
    if (!n) return value;
    if (!n->is_string()) fail(origin_, full(key), "must be a string", "a quoted string");
    return n->as_string()->get();
  }
  std::string choice(const std::string& key, std::string value, const std::vector<std::string>& allowed) {
    const std::string v = text(key, std::move(value));
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "\"" : ", \"") + a + "\"";
    if (std::find(allowed.begin(), allowed.end(), v) == allowed.end())
      fail(origin_, full(key), "= \"" + v + "\" is not a known choice", list);
    return v;
  }
  bool boolean(const std::string& key, bool value) {
    const toml::node* n = find(key);
    if (!n) return value;
    if (!n->is_boolean()) fail(origin_, full(key), "must be true or false", "true, false");
    return n->as_boolean()->get();
  }
  // Two numbers, each in `range`.
  Point vector2(const std::string& key, Point value, const Range& range = kSigned) {
    const toml::node* n = find(key);
    if (!n) return value;
    const std::string allowed = "[x, y], each " + range.text();
    const toml::array* a = n->as_array();
    if (!a || a->size() != 2 || !(*a)[0].is_number() || !(*a)[1].is_number())
      fail(origin_, full(key), "must be an array of two numbers", allowed);
    const Point v(as_double((*a)[0]), as_double((*a)[1]));
    if (!v.allFinite()) fail(origin_, full(key), "must be finite", allowed);
    if (!range.contains(v.x()) || !range.contains(v.y()))
      fail(origin_, full(key), "= [" + shortest(v.x()) + ", " + shortest(v.y()) + "] is out of range", allowed);
    return v;
  }
  // SPEC §10: a number in `range`, or a string, an expression in x, y, t compiled here
  // (case_expressions.cpp; a bad one fails with its column). Its text goes into
  // `expression` ("" for a number); returned: the number, a constant expression's
  // value, or a varying one's magnitude on `box` = [x_min, y_min, x_max, y_max] at t = 0
  // (the note above StructureParams, io/case.hpp).
  double number_or_expression(const std::string& key, double value, const Range& range, std::string& expression,
                              const std::array<double, 4>& box);
  // [a, b], each a number in `range` or an expression as above; two numbers read as vector2.
  Point vector2_or_expressions(const std::string& key, Point value, std::array<std::string, 2>& expressions,
                               const std::array<double, 4>& box, const Range& range = kSigned);
  // A width (a number, m) or a box [x_min, y_min, x_max, y_max].
  void band(const std::string& key, double& width, std::optional<std::array<double, 4>>& box) {
    const toml::node* n = find(key);
    if (!n) return;
    const std::string allowed = "a width in [1e-30, 1e30] m, or a box [x_min, y_min, x_max, y_max] with x_min < x_max, y_min < y_max";
    if (n->is_number()) {
      width = number(key, width, kSize);
      return;
    }
    const toml::array* a = n->as_array();
    if (!a || a->size() != 4) fail(origin_, full(key), "must be a number or an array of four numbers", allowed);
    std::array<double, 4> b{};
    for (std::size_t i = 0; i < 4; ++i) {
      if (!(*a)[i].is_number()) fail(origin_, full(key), "must be a number or an array of four numbers", allowed);
      b[i] = as_double((*a)[i]);
      if (!kSigned.contains(b[i])) fail(origin_, full(key), "has " + shortest(b[i]) + ", out of range", allowed);
    }
    if (!(b[0] < b[2] && b[1] < b[3])) fail(origin_, full(key), "is an empty box", allowed);
    box = b;
  }
  // The array under `key` (null if absent or not an array), read.
  const toml::array* array(const std::string& key) {
    const toml::node* n = find(key);
    return n ? n->as_array() : nullptr;
  }
  // Whether the section sets `key` (without reading it).
  bool has(const std::string& key) const { return table_ && table_->contains(key); }
  void reject_unknown() const {
    if (!table_) return;
    for (auto&& [k, v] : *table_) {
      const std::string key(k.str());
      if (!read_.count(key)) {
        std::string known;
        for (const auto& r : read_) known += (known.empty() ? "" : ", ") + r;
        fail(origin_, full(key), "is not a known key", known);
      }
    }
  }

 private:
  const toml::node* find(const std::string& key) {
    if (read_.insert(key).second && known_) known_->push_back(full(key));
    return table_ ? table_->get(key) : nullptr;
  }
  std::string full(const std::string& key) const { return name_.empty() ? key : name_ + "." + key; }

  const toml::table* table_;
  std::string name_;
  const Origin& origin_;
  std::vector<std::string>* known_;
  std::set<std::string> read_;
};

inline const toml::table* section_table(const toml::table& root, const std::string& name, const Origin& origin) {
  const toml::node* n = root.get(name);
  if (!n) return nullptr;
  if (!n->is_table()) fail(origin, name, "must be a table ([" + name + "])", "");
  return n->as_table();
}

// output.probes of the [output] section (case_probes.cpp).
// output.<name> (probes, fluid_probes): [[x, y], ...].
std::vector<Point> read_probes(Section& output, const Origin& origin, const std::string& name = "probes");

}  // namespace fsi::case_detail
