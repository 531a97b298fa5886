// Option tables: one definition per option (name, type, limits, default, help) from which every
// front door is made. The command line adds one flag per row, the batch manifest accepts one
// column per row, and the Python module one keyword per row; all of them hand the text the user
// gave to the library, which parses and checks it here, so that a value is refused with the same
// message whichever door it came through.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "sphereset/status.hpp"

namespace sphereset {

enum class OptionType {
  kInteger,   // a whole number in [min, max]
  kUnsigned,  // a whole number from 0 to 2^64 - 1 (seeds)
  kReal,      // a finite number in [min, max] (or (min, max] with above_min)
  kChoice,    // one of `choices`
};

struct OptionSpec {
  const char* name;  // the library's name: the Python keyword and the manifest column
  const char* flag;  // the command line's flags, CLI11 style ("-n,--spheres")
  OptionType type;
  double min = 0.0, max = 0.0;           // kInteger, kReal: inclusive bounds (but see above_min)
  std::span<const char* const> choices;  // kChoice
  const char* default_text;              // the default as help shows it
  const char* help;
  // A keyed row ("LINK" for per-link values): the text is KEY=VALUE, VALUE parsed as `type`
  // says, and the row may be given once per key. Null for plain rows.
  const char* key = nullptr;
  // A word accepted in place of a number on kReal rows ("auto"): the value is kAutomatic and
  // the library chooses it from the input. Null when the row takes numbers only.
  const char* automatic = nullptr;
  // kReal rows: `min` itself is refused, a value must be above it (limits and tolerances, where
  // 0 would mean none: the user leaves the option out instead).
  bool above_min = false;
  // kReal rows: the number may end in '%' (OptionValue::percent), checked against the same
  // bounds; what it is a percentage of is the row's own (its help says).
  bool percent = false;
};
// The value of a kReal row given its `automatic` word.
inline constexpr double kAutomatic = -1.0;

// Parsed values of one option, as the table's setters receive them.
struct OptionValue {
  int64_t integer = 0;            // kInteger
  uint64_t unsigned_integer = 0;  // kUnsigned
  double real = 0.0;              // kReal
  std::string choice;             // kChoice
  std::string key;                // keyed rows: the text before the last '='
  bool percent = false;           // kReal rows with OptionSpec::percent: the number ended in '%'
  // A percent row's value in its two forms, one of them 0: the length (given without '%') and
  // the fraction (the percentage over 100).
  double length() const { return percent ? 0.0 : real; }
  double fraction() const { return percent ? real / 100.0 : 0.0; }
};

// `text` parsed and checked as `spec` says. kInvalidArgument "NAME 'TEXT': expected an integer
// from 1 to 1000000" (or "a number from 0 to 16", "an integer from 0 to 18446744073709551615",
// "fast, default or best"; "a number above 0 and at most 1e+30" for an above_min row) for anything
// else, including trailing characters, NaN, infinities, numbers out of range and signs on unsigned
// values. A keyed row's text is KEY=VALUE (split at the last '='; KEY not empty): "NAME 'TEXT':
// expected LINK=VALUE, VALUE an integer from 0 to 10". A percent row's number may end in one '%',
// taken off before the range is checked (not after the automatic word); its message adds
// ", optionally followed by %" and quotes the text as given.
Expected<OptionValue> parseOption(const OptionSpec& spec, const std::string& text);

// "n, quality, seed, ..." : the names of a table, for messages listing them.
std::string optionNames(std::span<const OptionSpec> table);

// The row named `name`, or null.
const OptionSpec* findOption(std::span<const OptionSpec> table, const std::string& name);

// A row of `table` and `text` parsed by it, as every table's setter and checker receives them.
struct TableValue {
  const OptionSpec* spec = nullptr;
  OptionValue value;
};
// kInvalidArgument "unknown WHAT option 'NAME' (expected n, quality, ...)" when `table` has no
// row `name`; else parseOption's result for that row.
Expected<TableValue> parseTableOption(std::span<const OptionSpec> table, const char* what,
                                      const std::string& name, const std::string& text);

// The text a user would type for `value`: the shortest that reads back as it ("-1", "0.5",
// "1e+200", "nan"). Every door that hands a number to a table as text writes it so.
std::string optionText(double value);

// A value already in a struct checked against its row, as if a user had typed it: the shortest
// text that reads back as `value` ("1e+200", "0.5", "nan") through parseTableOption, so a
// struct set in code is refused with the message a typed value gets. `key` prefixes the text
// as KEY= for keyed rows; `percent` suffixes it with '%' for a percent row's value given as the
// percentage a user types (the row refuses it if it is not a percent row).
Status checkTableValue(std::span<const OptionSpec> table, const char* what, const std::string& name,
                       double value, const std::string& key = {}, bool percent = false);

}  // namespace sphereset
