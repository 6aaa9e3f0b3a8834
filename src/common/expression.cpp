#include "common/expression.hpp"

#include <muParser.h>

#include <algorithm>
#include <cctype>
#include <limits>
#include <numbers>

namespace fsi {
namespace {

// Longer texts are not what a case's load looks like; the bound keeps muparser's own
// (10 000 characters) and its work on a fuzzer's input small.
constexpr std::size_t kMaxLength = 1000;

std::string lower_first(std::string s) {
  if (!s.empty()) s[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(s[0])));
  return s;
}

// muparser's message without the position it appends ("... found at position 11."):
// the column says where, counted from 1.
std::string without_position(std::string message) {
  for (const char* tail : {" found at position", " at expression position", " at position"}) {
    const auto p = message.find(tail);
    if (p != std::string::npos) {
      message.erase(p);
      break;
    }
  }
  while (!message.empty() && (message.back() == '.' || message.back() == ' ')) message.pop_back();
  return lower_first(message);
}

ExpressionError described(const mu::Parser::exception_type& e, const std::string& text) {
  const int pos = e.GetPos();
  const int column = pos < 0 ? 0 : std::min(pos, static_cast<int>(text.size())) + 1;
  std::string token = e.GetToken();  // muparser's runs on past a stray character: its first word
  token = token.substr(0, std::min(token.find_first_of(" \t\r\n"), token.size()));
  const auto name_character = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  switch (e.GetCode()) {
    case mu::ecUNASSIGNABLE_TOKEN: {  // a name that is neither a variable nor a function, or a bad number
      if (!token.empty() && (std::isdigit(static_cast<unsigned char>(token[0])) || token[0] == '.'))
        return {"bad number \"" + token + "\"", column};
      if (!std::all_of(token.begin(), token.end(), name_character))
        return {"unexpected \"" + token + "\"", column};
      std::size_t next = static_cast<std::size_t>(std::max(pos, 0)) + token.size();
      while (next < text.size() && text[next] == ' ') ++next;
      if (next < text.size() && text[next] == '(') return {"unknown function \"" + token + "\"", column};
      return {"unknown variable \"" + token + "\"", column};
    }
    case mu::ecUNEXPECTED_EOF:
      return {"ends too early", column};
    case mu::ecEMPTY_EXPRESSION:
      return {"is empty", 0};
    default:
      return {without_position(e.GetMsg()), column};
  }
}

// muparser assigns with "=" (x = 3 sets x): a load has no business doing that.
void refuse_assignment(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '=') continue;
    const bool compares = (i > 0 && std::string("<>!=").find(text[i - 1]) != std::string::npos) ||
                          (i + 1 < text.size() && text[i + 1] == '=');
    if (!compares) throw ExpressionError("\"=\" assigns (\"==\" compares)", static_cast<int>(i) + 1);
  }
}

// "1, 2" gives two values: the column of the first comma outside any parentheses.
int top_level_comma(const std::string& text) {
  int depth = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '(') ++depth;
    if (text[i] == ')') --depth;
    if (text[i] == ',' && depth == 0) return static_cast<int>(i) + 1;
  }
  return 0;
}

}  // namespace

ExpressionError::ExpressionError(const std::string& problem_, int column_)
    : std::runtime_error(problem_ + (column_ > 0 ? " at column " + std::to_string(column_) : "")),
      problem(problem_),
      column(column_) {}

struct Expression::Compiled {
  std::string text;
  double x = 0, y = 0, t = 0;  // bound to the parser by address: Compiled never moves
  mu::Parser parser;
  bool varies = true;

  explicit Compiled(std::string text_) : text(std::move(text_)) {
    if (text.size() > kMaxLength)
      throw ExpressionError("is longer than " + std::to_string(kMaxLength) + " characters", 0);
    refuse_assignment(text);
    try {
      parser.DefineVar("x", &x);
      parser.DefineVar("y", &y);
      parser.DefineVar("t", &t);
      // pi, and muparser's own _pi and _e to the last digit (Debian's 2.3.3 has
      // _pi = 3.141592653589, twelve digits).
      parser.DefineConst("pi", std::numbers::pi);
      parser.DefineConst("_pi", std::numbers::pi);
      parser.DefineConst("_e", std::numbers::e);
      parser.SetExpr(text);
      parser.Eval();  // muparser parses on the first evaluation: its errors now, not at the first point
      if (parser.GetNumResults() != 1)
        throw ExpressionError("\",\" starts a second value", top_level_comma(text));
      varies = !parser.GetUsedVar().empty();
      parser.Eval();  // GetUsedVar leaves the text to be parsed again: compiled once more, here
    } catch (const mu::Parser::exception_type& e) {
      throw described(e, text);
    } catch (const ExpressionError&) {
      throw;
    } catch (const std::exception& e) {  // anything else muparser meets in a user's text is still the text's fault
      throw ExpressionError(std::string("cannot be read (") + e.what() + ")", 0);
    }
  }
  Compiled(const Compiled&) = delete;
  Compiled& operator=(const Compiled&) = delete;
};

Expression::Expression(const std::string& text) : compiled_(std::make_unique<Compiled>(text)) {}

// A parser copied by muparser would keep the addresses of the other's variables: the
// copy compiles the text again around its own.
Expression::Expression(const Expression& other) : compiled_(std::make_unique<Compiled>(other.text())) {}

Expression& Expression::operator=(const Expression& other) {
  if (this != &other) compiled_ = std::make_unique<Compiled>(other.text());
  return *this;
}

Expression::Expression(Expression&&) noexcept = default;
Expression& Expression::operator=(Expression&&) noexcept = default;
Expression::~Expression() = default;

double Expression::operator()(double x, double y, double t) const {
  Compiled& c = *compiled_;
  c.x = x, c.y = y, c.t = t;
  try {
    return c.parser.Eval();
  } catch (const mu::Parser::exception_type&) {  // a compiled text does not throw; if it did, no value
    return std::numeric_limits<double>::quiet_NaN();
  }
}

const std::string& Expression::text() const { return compiled_->text; }

bool Expression::varies() const { return compiled_->varies; }

}  // namespace fsi
