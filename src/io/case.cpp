#include "io/case.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "common/errors.hpp"

namespace fsi {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// A TOML number as a double. toml++'s value<double>() refuses integers that a double
// cannot hold exactly (found by fuzzing: L = 30000000020000000 threw
// bad_optional_access); the nearest double is what a user means.
double as_double(const toml::node& n) {
  if (const auto* i = n.as_integer()) return static_cast<double>(i->get());
  return n.as_floating_point()->get();
}

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// An interval with open or closed ends, and its text for messages.
struct Range {
  double lo = -inf, hi = inf;
  bool lo_closed = false, hi_closed = false;
  bool contains(double v) const {
    return (lo_closed ? v >= lo : v > lo) && (hi_closed ? v <= hi : v < hi);
  }
  std::string text() const {
    if (hi == inf) return lo == -inf ? "any finite number" : (lo_closed ? ">= " : "> ") + fmt(lo);
    if (lo == -inf) return (hi_closed ? "<= " : "< ") + fmt(hi);
    return std::string(lo_closed ? "[" : "(") + fmt(lo) + ", " + fmt(hi) + (hi_closed ? "]" : ")");
  }
};
const Range kAny{};
const Range kPositive{0, inf};
const Range kNonNegative{0, inf, true, false};
Range open(double a, double b) { return {a, b, false, false}; }
Range left_open(double a, double b) { return {a, b, false, true}; }

// Where each key came from: the case file, or a --set override.
struct Origin {
  std::string file;
  std::set<std::string> overridden;
  std::string of(const std::string& key) const {
    return overridden.count(key) ? "--set " + key : file;
  }
};

[[noreturn]] void fail(const Origin& origin, const std::string& key, const std::string& problem,
                       const std::string& allowed) {
  throw InputError(origin.of(key) + ": " + key + " " + problem +
                   (allowed.empty() ? "" : "; allowed: " + allowed));
}

// Reads one section, remembering which keys it consumed so the rest can be rejected.
class Section {
 public:
  Section(const toml::table* table, std::string name, const Origin& origin)
      : table_(table), name_(std::move(name)), origin_(origin) {}

  double number(const std::string& key, double value, const Range& range = kAny) {
    const toml::node* n = find(key);
    if (!n) return value;
    if (!n->is_number()) fail(origin_, full(key), "must be a number", range.text());
    const double v = as_double(*n);
    if (!std::isfinite(v)) fail(origin_, full(key), "must be finite", range.text());
    if (!range.contains(v)) fail(origin_, full(key), "= " + fmt(v) + " is out of range", range.text());
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
  Point vector2(const std::string& key, Point value) {
    const toml::node* n = find(key);
    if (!n) return value;
    const toml::array* a = n->as_array();
    if (!a || a->size() != 2 || !(*a)[0].is_number() || !(*a)[1].is_number())
      fail(origin_, full(key), "must be an array of two numbers", "[x, y], finite");
    const Point v(as_double((*a)[0]), as_double((*a)[1]));
    if (!v.allFinite()) fail(origin_, full(key), "must be finite", "[x, y], finite");
    return v;
  }
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
    read_.insert(key);
    return table_ ? table_->get(key) : nullptr;
  }
  std::string full(const std::string& key) const { return name_.empty() ? key : name_ + "." + key; }

  const toml::table* table_;
  std::string name_;
  const Origin& origin_;
  std::set<std::string> read_;
};

const toml::table* section_table(const toml::table& root, const std::string& name, const Origin& origin) {
  const toml::node* n = root.get(name);
  if (!n) return nullptr;
  if (!n->is_table()) fail(origin, name, "must be a table ([" + name + "])", "");
  return n->as_table();
}

// "section.key=value" (or "key=value" for a top-level key such as name): the value
// parsed as TOML, or taken as a bare string.
void apply_override(toml::table& root, const std::string& text, Origin& origin) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set " + text + ": expected section.key=value (for example coupling.omega=0.2)");
  const std::string path = text.substr(0, eq), value = text.substr(eq + 1);
  const auto dot = path.find('.');
  const std::string section = dot == std::string::npos ? "" : path.substr(0, dot);
  const std::string key = dot == std::string::npos ? path : path.substr(dot + 1);
  if ((dot != std::string::npos && (section.empty() || key.empty())) || key.find('.') != std::string::npos)
    throw InputError("--set " + text + ": expected section.key=value (for example coupling.omega=0.2)");
  toml::table holder;
  try {
    holder = toml::parse("v = " + value);
  } catch (const toml::parse_error&) {
    holder.insert_or_assign("v", value);  // a bare word such as aitken
  }
  toml::table* t = &root;
  if (!section.empty()) {
    if (!root.contains(section)) root.insert(section, toml::table{});
    t = root[section].as_table();
    if (!t) throw InputError("--set " + text + ": " + section + " is not a section");
  } else if (key != "name") {
    throw InputError("--set " + text + ": expected section.key=value (for example coupling.omega=0.2)");
  }
  t->insert_or_assign(key, *holder.get("v"));
  origin.overridden.insert(path);
}

std::string resolve_path(const std::string& file, const std::string& case_path) {
  if (file.empty() || case_path.empty()) return file;
  const std::filesystem::path p(file);
  if (p.is_absolute()) return file;
  return (std::filesystem::path(case_path).parent_path() / p).lexically_normal().string();
}

// Distance from a point to the rectangle [0,L]×[0,H].
double distance_to_rectangle(double x, double y, double L, double H) {
  const double dx = std::max({0.0 - x, 0.0, x - L}), dy = std::max({0.0 - y, 0.0, y - H});
  return std::hypot(dx, dy);
}

void check_geometry(const Case& c, const Origin& origin) {
  const auto& s = c.structure;
  const auto& o = c.obstacle;
  if (!(o.xc_min() > 0 && o.xc_max() < s.L))
    fail(origin, "obstacle.x0", "puts Gamma_C = (" + fmt(o.xc_min()) + ", " + fmt(o.xc_max()) +
                                    ") outside the structure's bottom side",
         "x0 - gamma*r > 0 and x0 + gamma*r < structure.L = " + fmt(s.L));
  if (distance_to_rectangle(o.x0, o.y0, s.L, s.H) < o.r || o.y0 + o.r > 0)
    fail(origin, "obstacle.y0", "= " + fmt(o.y0) + " puts the structure inside the obstacle at rest",
         "y0 + r <= 0 (the disk's top below the structure's bottom y = 0)");
  const double est_s = std::max(2.4 * s.L * s.H / (s.h * s.h), 2.0 * s.L / s.h);
  if (s.mesh.empty() && est_s > kMaxStructureTriangles)
    fail(origin, "structure.h", "= " + fmt(s.h) + " would need about " + fmt(est_s) +
                                    " triangles, above the limit of " + fmt(kMaxStructureTriangles),
         ">= " + fmt(std::sqrt(2.4 * s.L * s.H / kMaxStructureTriangles)));
  if (!c.fluid) return;
  const auto& f = *c.fluid;
  if (!(o.x0 - o.r > 0 && o.x0 + o.r < f.L1 && o.y0 - o.r > -f.H2 && o.y0 + o.r < f.H1))
    fail(origin, "obstacle.r", "= " + fmt(o.r) + " puts the obstacle outside the fluid box",
         "the disk inside (0, L1) x (-H2, H1) = (0, " + fmt(f.L1) + ") x (" + fmt(-f.H2) + ", " +
             fmt(f.H1) + ")");
  if (!(s.L < f.L1))
    fail(origin, "structure.L", "= " + fmt(s.L) + " does not fit in the fluid box",
         "L < fluid.L1 = " + fmt(f.L1));
  if (!(s.H < f.H1))
    fail(origin, "structure.H", "= " + fmt(s.H) + " does not fit in the fluid box",
         "H < fluid.H1 = " + fmt(f.H1));
  const double area = f.L1 * (f.H1 + f.H2) - std::numbers::pi * o.r * o.r;
  const double est_f = 2.4 * area / (f.h * f.h);
  if (f.mesh.empty() && est_f > kMaxFluidTriangles)
    fail(origin, "fluid.h", "= " + fmt(f.h) + " would need about " + fmt(est_f) +
                                " triangles, above the limit of " + fmt(kMaxFluidTriangles),
         ">= " + fmt(std::sqrt(2.4 * area / kMaxFluidTriangles)) + " for this box");
}

Case read_case(const toml::table& root, const Origin& origin, const std::string& case_path,
               bool has_fluid_default) {
  Case c;
  c.source = origin.file;
  {
    Section top(&root, "", origin);
    c.name = top.text("name", case_path.empty() ? c.name
                                                : std::filesystem::path(case_path).stem().string());
    for (auto&& [k, v] : root) {
      const std::string key(k.str());
      static const std::set<std::string> sections = {"structure", "obstacle", "fluid", "coupling",
                                                     "contact", "output", "name"};
      if (!sections.count(key))
        fail(origin, key, "is not a known key or section",
             "name, [structure], [obstacle], [fluid], [coupling], [contact], [output]");
    }
    if (c.name.empty() || c.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                   "0123456789._-") != std::string::npos)
      fail(origin, "name", "= \"" + c.name + "\" cannot name an output directory",
           "letters, digits, '.', '_', '-'");
  }
  {
    Section s(section_table(root, "structure", origin), "structure", origin);
    auto& p = c.structure;
    p.L = s.number("L", p.L, kPositive);
    p.H = s.number("H", p.H, kPositive);
    p.E = s.number("E", p.E, kPositive);
    p.nu = s.number("nu", p.nu, open(0, 0.5));
    p.f = s.vector2("f", p.f);
    p.h_N = s.vector2("h_N", p.h_N);
    p.h = s.number("h", p.h, left_open(0, p.L / 2));
    p.mesh = resolve_path(s.text("mesh", ""), case_path);
    s.reject_unknown();
  }
  {
    Section s(section_table(root, "obstacle", origin), "obstacle", origin);
    auto& p = c.obstacle;
    p.x0 = s.number("x0", p.x0);
    p.y0 = s.number("y0", p.y0);
    p.r = s.number("r", p.r, kPositive);
    p.gamma = s.number("gamma", p.gamma, open(0, 1));
    s.reject_unknown();
  }
  const toml::table* fluid = section_table(root, "fluid", origin);
  if (fluid || has_fluid_default) {
    Section s(fluid, "fluid", origin);
    FluidParams p;
    p.L1 = s.number("L1", p.L1, kPositive);
    p.H1 = s.number("H1", p.H1, kPositive);
    p.H2 = s.number("H2", p.H2, kPositive);
    p.mu = s.number("mu", p.mu, kPositive);
    p.f = s.vector2("f", p.f);
    p.Vmax = s.number("Vmax", p.Vmax);
    p.h = s.number("h", p.h, left_open(0, c.obstacle.r));
    p.mesh = resolve_path(s.text("mesh", ""), case_path);
    p.chi = s.choice("chi", p.chi, {"barycentre", "area-fraction"});
    p.factorization = s.choice("factorization", p.factorization, {"schur", "whole"});
    p.keep_far_factors_mb = s.number("keep_far_factors_mb", p.keep_far_factors_mb, kNonNegative);
    s.reject_unknown();
    c.fluid = p;
  } else {
    c.fluid.reset();
  }
  {
    Section s(section_table(root, "coupling", origin), "coupling", origin);
    auto& p = c.coupling;
    // Below 1e-12 the penalty outweighs the viscous term by over 1e10 per element
    // (hF = 0.01, μ_F = 0.0035) and the fluid system loses its digits; ε = 1e-300
    // overflows outright.
    p.eps = s.number("eps", p.eps, {1e-12, inf, true, false});
    p.omega = s.number("omega", p.omega, left_open(0, 1));
    p.tol = s.number("tol", p.tol, kPositive);
    p.max_iterations = s.integer("max_iterations", p.max_iterations, 0, kMaxIterations);
    p.scheme = s.choice("scheme", p.scheme, {"constant", "aitken", "iqn-ils"});
    s.reject_unknown();
  }
  {
    Section s(section_table(root, "contact", origin), "contact", origin);
    c.contact.solver = s.choice("solver", c.contact.solver, {"active-set", "ipopt"});
    s.reject_unknown();
  }
  {
    Section s(section_table(root, "output", origin), "output", origin);
    c.output.dir = s.text("dir", "out/" + c.name);
    c.output.png = s.boolean("png", c.output.png);
    c.output.vtu = s.boolean("vtu", c.output.vtu);
    if (c.output.dir.empty()) fail(origin, "output.dir", "is empty", "a directory path");
    s.reject_unknown();
  }
  check_geometry(c, origin);
  return c;
}

}  // namespace

Case load_case(const std::string& path, const std::vector<std::string>& overrides) {
  Origin origin{path.empty() ? "(built-in paper-7.2 case)" : path, {}};
  toml::table root;
  if (!path.empty()) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
      throw InputError(path + ": no such case file");
    try {
      root = toml::parse_file(path);
    } catch (const toml::parse_error& e) {
      throw InputError(path + ":" + std::to_string(e.source().begin.line) + ": " +
                       std::string(e.description()));
    }
  }
  for (const auto& o : overrides) apply_override(root, o, origin);
  return read_case(root, origin, path, /*has_fluid_default=*/path.empty());
}

Case load_case_text(const std::string& text, const std::string& origin_name,
                    const std::vector<std::string>& overrides) {
  Origin origin{origin_name, {}};
  toml::table root;
  try {
    root = toml::parse(text, origin_name);
  } catch (const toml::parse_error& e) {
    throw InputError(origin_name + ":" + std::to_string(e.source().begin.line) + ": " +
                     std::string(e.description()));
  }
  for (const auto& o : overrides) apply_override(root, o, origin);
  return read_case(root, origin, "", /*has_fluid_default=*/false);
}

std::string to_toml(const Case& c) {
  auto vec = [](const Point& p) { return toml::array{p.x(), p.y()}; };
  toml::table t;
  t.insert("name", c.name);
  const auto& s = c.structure;
  toml::table st{{"L", s.L}, {"H", s.H}, {"E", s.E}, {"nu", s.nu}, {"f", vec(s.f)},
                 {"h_N", vec(s.h_N)}, {"h", s.h}};
  if (!s.mesh.empty()) st.insert("mesh", s.mesh);
  t.insert("structure", st);
  const auto& o = c.obstacle;
  t.insert("obstacle", toml::table{{"x0", o.x0}, {"y0", o.y0}, {"r", o.r}, {"gamma", o.gamma}});
  if (c.fluid) {
    const auto& f = *c.fluid;
    toml::table ft{{"L1", f.L1}, {"H1", f.H1}, {"H2", f.H2}, {"mu", f.mu},   {"f", vec(f.f)},
                   {"Vmax", f.Vmax}, {"h", f.h}, {"chi", f.chi}, {"factorization", f.factorization},
                   {"keep_far_factors_mb", f.keep_far_factors_mb}};
    if (!f.mesh.empty()) ft.insert("mesh", f.mesh);
    t.insert("fluid", ft);
  }
  const auto& k = c.coupling;
  t.insert("coupling", toml::table{{"eps", k.eps}, {"omega", k.omega}, {"tol", k.tol},
                                   {"max_iterations", k.max_iterations}, {"scheme", k.scheme}});
  t.insert("contact", toml::table{{"solver", c.contact.solver}});
  t.insert("output", toml::table{{"dir", c.output.dir}, {"png", c.output.png}, {"vtu", c.output.vtu}});
  std::ostringstream out;
  out << t << "\n";
  return out.str();
}

}  // namespace fsi
