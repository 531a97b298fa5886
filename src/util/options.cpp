// Parsing and checking an option's text against its row of an option table (options.hpp): the
// one place where a value a user typed becomes a number or a name.
#include "sphereset/options.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "util/number_text.hpp"

namespace sphereset {
namespace {

// "fast, default or best".
std::string choiceList(std::span<const char* const> choices) {
  std::string s;
  for (size_t i = 0; i < choices.size(); ++i)
    s += (i == 0 ? "" : (i + 1 == choices.size() ? " or " : ", ")) + std::string(choices[i]);
  return s;
}

std::string expectation(const OptionSpec& spec) {
  switch (spec.type) {
    case OptionType::kInteger:
      return "an integer from " + detail::numberText(spec.min) + " to " +
             detail::numberText(spec.max);
    case OptionType::kUnsigned:
      return "an integer from 0 to " + std::to_string(std::numeric_limits<uint64_t>::max());
    case OptionType::kReal:
      return (spec.max == std::numeric_limits<double>::max()
                  ? "a finite number " + std::string(spec.above_min ? "> " : ">= ") +
                        detail::numberText(spec.min)
              : spec.above_min ? "a number above " + detail::numberText(spec.min) +
                                     " and at most " + detail::numberText(spec.max)
                               : "a number from " + detail::numberText(spec.min) + " to " +
                                     detail::numberText(spec.max)) +
             (spec.automatic ? " or " + std::string(spec.automatic) : std::string()) +
             (spec.percent ? ", optionally followed by %" : "");
    case OptionType::kChoice:
      return choiceList(spec.choices);
  }
  return {};
}

// The whole of `text` as an integer of type T, nothing before or after it.
template <class T>
bool wholeInteger(const std::string& text, T* out) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, *out);
  return ec == std::errc() && ptr == end && !text.empty();
}

}  // namespace

Expected<OptionValue> parseOption(const OptionSpec& spec, const std::string& full_text) {
  OptionValue v;
  std::string text = full_text;
  if (spec.key) {
    const size_t eq = full_text.rfind('=');
    if (eq == std::string::npos || eq == 0)
      return Error{ErrorCode::kInvalidArgument, std::string(spec.name) + " '" + full_text +
                                                    "': expected " + spec.key + "=VALUE, VALUE " +
                                                    expectation(spec)};
    v.key = full_text.substr(0, eq);
    text = full_text.substr(eq + 1);
  }
  bool ok = false;
  switch (spec.type) {
    case OptionType::kInteger:
      ok = wholeInteger(text, &v.integer) && static_cast<double>(v.integer) >= spec.min &&
           static_cast<double>(v.integer) <= spec.max;
      break;
    case OptionType::kUnsigned:
      ok = wholeInteger(text, &v.unsigned_integer);
      break;
    case OptionType::kReal: {
      if (spec.automatic && text == spec.automatic) {
        v.real = kAutomatic;
        ok = true;
        break;
      }
      v.percent = spec.percent && !text.empty() && text.back() == '%';
      if (v.percent) text.pop_back();
      v.real = 0.0;
      ok = detail::parseNumber(text, &v.real) && std::isfinite(v.real) &&
           (spec.above_min ? v.real > spec.min : v.real >= spec.min) && v.real <= spec.max;
      break;
    }
    case OptionType::kChoice:
      for (const char* c : spec.choices) ok = ok || text == c;
      v.choice = text;
      break;
  }
  if (ok) return v;
  return Error{ErrorCode::kInvalidArgument,
               std::string(spec.name) + " '" + full_text + "': expected " +
                   (spec.key ? std::string(spec.key) + "=VALUE, VALUE " : std::string()) +
                   expectation(spec)};
}

std::string optionNames(std::span<const OptionSpec> table) {
  std::string s;
  for (const OptionSpec& o : table) s += (s.empty() ? "" : ", ") + std::string(o.name);
  return s;
}

const OptionSpec* findOption(std::span<const OptionSpec> table, const std::string& name) {
  for (const OptionSpec& o : table)
    if (name == o.name) return &o;
  return nullptr;
}

Expected<TableValue> parseTableOption(std::span<const OptionSpec> table, const char* what,
                                      const std::string& name, const std::string& text) {
  const OptionSpec* spec = findOption(table, name);
  if (!spec)
    return Error{ErrorCode::kInvalidArgument, std::string("unknown ") + what + " option '" + name +
                                                  "' (expected " + optionNames(table) + ")"};
  auto v = parseOption(*spec, text);
  if (!v) return v.error();
  return TableValue{spec, std::move(v).value()};
}

std::string optionText(double value) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, r.ptr);
}

Status checkTableValue(std::span<const OptionSpec> table, const char* what, const std::string& name,
                       double value, const std::string& key, bool percent) {
  // Whole numbers for integer rows as a user types them ("10000000", not "1e+07").
  const OptionSpec* spec = findOption(table, name);
  const bool whole = spec && spec->type != OptionType::kReal && std::isfinite(value) &&
                     value == std::floor(value) && std::fabs(value) < 9e18;
  std::string text = whole ? std::to_string(static_cast<int64_t>(value)) : optionText(value);
  if (spec && spec->automatic && value == kAutomatic) text = spec->automatic;
  if (percent) text += "%";
  if (!key.empty()) text = key + "=" + text;
  if (auto v = parseTableOption(table, what, name, text); !v) return v.error();
  return {};
}

}  // namespace sphereset
