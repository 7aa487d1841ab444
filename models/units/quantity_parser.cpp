#include "models/units/quantity_parser.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "models/units/angle.hpp"

namespace feedflow {
namespace {

struct UnitSymbol {
  std::string_view symbol;
  double factor;  // SI value of one unit
  Dimension dimension;
  bool takes_prefix;
};

constexpr double kPi = std::numbers::pi;

// Units a case file may use. Prefixable ones accept the SI prefixes of kPrefixes.
constexpr UnitSymbol kUnits[] = {
    {"m", 1.0, dim::length, true},
    {"in", 0.0254, dim::length, false},
    {"ft", 0.3048, dim::length, false},
    {"g", 1e-3, dim::mass, true},
    {"t", 1000.0, dim::mass, false},
    {"lb", 0.45359237, dim::mass, false},
    {"s", 1.0, dim::time, true},
    {"min", 60.0, dim::time, false},
    {"h", 3600.0, dim::time, false},
    {"rad", 1.0, dim::angle, true},
    {"deg", kDegree, dim::angle, false},
    {"degree", kDegree, dim::angle, false},
    {"degrees", kDegree, dim::angle, false},
    {"\xC2\xB0", kDegree, dim::angle, false},  // °
    {"rev", 2.0 * kPi, dim::angle, false},
    {"rpm", kRpm, dim::angular_speed, false},
    {"Hz", 1.0, dim::rate, true},
    {"N", 1.0, dim::force, true},
    {"Pa", 1.0, dim::pressure, true},
    {"bar", 1e5, dim::pressure, true},
    {"psi", 6894.757293168361, dim::pressure, false},
    {"J", 1.0, dim::energy, true},
    {"W", 1.0, dim::energy / dim::time, true},
    {"L", 1e-3, dim::volume, false},
    {"%", 0.01, dim::dimensionless, false},
};

struct Prefix {
  std::string_view symbol;
  double factor;
};

constexpr Prefix kPrefixes[] = {
    {"G", 1e9}, {"M", 1e6}, {"k", 1e3}, {"c", 1e-2}, {"m", 1e-3},
    {"u", 1e-6}, {"\xC2\xB5", 1e-6} /* µ */, {"n", 1e-9},
};

std::optional<Quantity> lookup_symbol(std::string_view s) {
  for (const auto& u : kUnits)
    if (u.symbol == s) return Quantity{u.factor, u.dimension};
  for (const auto& p : kPrefixes) {
    if (s.size() <= p.symbol.size() || s.substr(0, p.symbol.size()) != p.symbol) continue;
    const auto rest = s.substr(p.symbol.size());
    for (const auto& u : kUnits)
      if (u.takes_prefix && u.symbol == rest) return Quantity{p.factor * u.factor, u.dimension};
  }
  return std::nullopt;
}

bool is_symbol_byte(unsigned char c, std::string_view text, std::size_t i) {
  if (std::isalpha(c)) return true;
  // UTF-8 µ (C2 B5) and ° (C2 B0) are part of symbols; ² ³ · are not.
  if (c == 0xC2 && i + 1 < text.size()) {
    const auto next = static_cast<unsigned char>(text[i + 1]);
    return next == 0xB5 || next == 0xB0;
  }
  if (c == 0xB5 || c == 0xB0) return i > 0 && static_cast<unsigned char>(text[i - 1]) == 0xC2;
  return false;
}

[[noreturn]] void fail(std::string_view unit, const std::string& why) {
  throw UnitError("unit \"" + std::string(unit) + "\": " + why);
}

class UnitExpressionParser {
 public:
  explicit UnitExpressionParser(std::string_view text) : text_(text) {}

  Quantity parse() {
    Quantity result{1.0, dim::dimensionless};
    bool divide = false;
    bool expect_term = true;
    skip_spaces();
    while (pos_ < text_.size()) {
      if (!expect_term) {
        // A separator: '*', '.', '·', '/', or a space between two terms.
        if (peek() == '*' || peek() == '.') {
          ++pos_;
        } else if (peek() == '/') {
          ++pos_;
          divide = true;
        } else if (at("\xC2\xB7")) {
          pos_ += 2;
        } else if (!had_space_) {
          fail(text_, "unexpected '" + std::string(1, peek()) + "'");
        }
        skip_spaces();
        expect_term = true;
        continue;
      }
      Quantity term = parse_term();
      if (divide) {
        result.si /= term.si;
        result.dimension = result.dimension / term.dimension;
      } else {
        result.si *= term.si;
        result.dimension = result.dimension * term.dimension;
      }
      divide = false;
      expect_term = false;
      had_space_ = skip_spaces();
    }
    if (expect_term && !text_.empty()) fail(text_, "ends with an operator");
    return result;
  }

 private:
  char peek() const { return text_[pos_]; }
  bool at(std::string_view s) const { return text_.substr(pos_, s.size()) == s; }
  bool skip_spaces() {
    const auto start = pos_;
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
    return pos_ > start;
  }

  Quantity parse_term() {
    const auto start = pos_;
    Quantity q;
    if (peek() == '1') {  // "1/s"
      ++pos_;
      q = Quantity{1.0, dim::dimensionless};
    } else if (peek() == '%') {
      ++pos_;
      q = *lookup_symbol("%");
    } else {
      while (pos_ < text_.size() &&
             is_symbol_byte(static_cast<unsigned char>(text_[pos_]), text_, pos_))
        ++pos_;
      const auto symbol = text_.substr(start, pos_ - start);
      if (symbol.empty()) fail(text_, "expected a unit symbol at '" + std::string(text_.substr(start)) + "'");
      const auto found = lookup_symbol(symbol);
      if (!found) fail(text_, "unknown unit '" + std::string(symbol) + "'");
      q = *found;
    }
    const int exponent = parse_exponent();
    return Quantity{std::pow(q.si, exponent), q.dimension.pow(exponent)};
  }

  int parse_exponent() {
    if (at("\xC2\xB2")) { pos_ += 2; return 2; }  // ²
    if (at("\xC2\xB3")) { pos_ += 2; return 3; }  // ³
    bool caret = false;
    if (pos_ < text_.size() && peek() == '^') { ++pos_; caret = true; }
    bool negative = false;
    if (caret && pos_ < text_.size() && peek() == '-') { ++pos_; negative = true; }
    const auto start = pos_;
    while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(peek()))) ++pos_;
    if (pos_ == start) {
      if (caret) fail(text_, "'^' must be followed by an integer exponent");
      return 1;
    }
    int value = 0;
    std::from_chars(text_.data() + start, text_.data() + pos_, value);
    if (value == 0 || value > 9) fail(text_, "exponent out of range");
    return negative ? -value : value;
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  bool had_space_ = false;
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string with_article(const std::string& noun) {
  const bool vowel = !noun.empty() && std::string_view("aeiou").find(noun.front()) != std::string_view::npos;
  return (vowel ? "an " : "a ") + noun;
}

}  // namespace

Quantity parse_unit(std::string_view unit) {
  unit = trim(unit);
  if (unit.empty() || unit == "-") return Quantity{1.0, dim::dimensionless};
  return UnitExpressionParser(unit).parse();
}

Quantity parse_quantity(std::string_view text) {
  const auto original = text;
  text = trim(text);
  if (text.empty()) throw UnitError("expected a number with a unit, got an empty string");
  std::size_t skip = (text.front() == '+') ? 1 : 0;
  double number = 0.0;
  const auto* begin = text.data() + skip;
  const auto* end = text.data() + text.size();
  // Only plain decimal numbers: from_chars would also take "inf" and "nan".
  if (begin == end || !(std::isdigit(static_cast<unsigned char>(*begin)) || *begin == '.' ||
                        (*begin == '-' && begin + 1 != end))) {
    throw UnitError("\"" + std::string(original) + "\" does not start with a number");
  }
  const auto [ptr, ec] = std::from_chars(begin, end, number);
  if (ec != std::errc() || !std::isfinite(number))
    throw UnitError("\"" + std::string(original) + "\" does not start with a finite number");
  const auto unit = text.substr(static_cast<std::size_t>(ptr - text.data()));
  const Quantity u = parse_unit(unit);
  return Quantity{number * u.si, u.dimension};
}

double parse_quantity_as(std::string_view text, const Dimension& expected, bool bare_number_is_si) {
  const Quantity q = parse_quantity(text);
  const bool bare = trim(text).find_first_not_of("+-.0123456789eE") == std::string_view::npos;
  if (bare && bare_number_is_si) return q.si;
  if (q.dimension != expected) {
    throw UnitError("expected " + with_article(dimension_name(expected)) + " (e.g. " +
                    example_value(expected) + "), got " +
                    (bare ? std::string("a bare number") : with_article(dimension_name(q.dimension))) +
                    " \"" + std::string(trim(text)) + "\"");
  }
  return q.si;
}

}  // namespace feedflow
