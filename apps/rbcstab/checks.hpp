#pragma once
// Range checks for numeric flags whose messages read like the library's ("--step: -1 must be > 0").
// (CLI11's PositiveNumber prints its bound as the 300-digit DBL_MAX.)
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <optional>
#include <sys/stat.h>
#include <string>
#include <vector>

#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"

namespace rbcstab::cli {

// The whole text converted by `convert` (std::stoll): false for an empty text or trailing
// characters ("", "0.1abc", "3.5" as an integer).
template <class T, class Convert>
bool parse_whole(const std::string& text, T& v, Convert convert) {
  std::size_t pos = 0;
  try {
    v = convert(text, &pos);
  } catch (const std::exception&) {
    return false;
  }
  return pos != 0 && pos == text.size();
}
inline bool parse_number(const std::string& text, double& v) {
  const std::optional<double> x = read_number(text);
  if (x) v = *x;
  return x.has_value();
}
inline bool parse_integer(const std::string& text, long long& v) {
  return parse_whole(text, v, [](const std::string& t, std::size_t* pos) { return std::stoll(t, pos); });
}

// Any number given in full, so that CLI11's own conversion (which reads "" as 0) never sees bad text;
// `range` says what the flag accepts (the library checks it after the scene is assembled).
inline CLI::Validator number_text(const std::string& range) {
  return CLI::Validator(
      [range](std::string& text) -> std::string {
        double v = 0;
        if (!parse_number(text, v)) return number_error(text) + " (" + range + ")";
        return {};
      },
      "", "NUMBER");
}

// An integer given in full; `range` says what the flag accepts (checked by the library).
inline CLI::Validator integer_text(const std::string& range) {
  return CLI::Validator(
      [range](std::string& text) -> std::string {
        long long v = 0;
        if (!parse_integer(text, v)) return "'" + text + "' is not an integer (" + range + ")";
        return {};
      },
      "", "INT");
}

// An integer given in full, within [lo, hi].
inline CLI::Validator integer_in(long long lo, long long hi) {
  const std::string range = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        long long v = 0;
        if (!parse_integer(text, v)) return "'" + text + "' is not an integer (must be " + range + ")";
        if (v < lo || v > hi) return text + " is out of range: must be " + range;
        return {};
      },
      range, "INT");
}

// Finite numbers above `bound` (strict) or at least `bound`.
inline CLI::Validator number_above(double bound, bool strict) {
  const std::string range = (strict ? "> " : ">= ") + CLI::detail::to_string(bound);
  return CLI::Validator(
      [bound, strict, range](std::string& text) -> std::string {
        double v = 0;
        if (!parse_number(text, v)) return number_error(text) + " (must be " + range + ")";
        if (!std::isfinite(v) || (strict ? !(v > bound) : !(v >= bound)))
          return text + " is out of range: must be finite and " + range;
        return {};
      },
      range, "RANGE");
}
// A file name or prefix: an empty one would write hidden files named only by their suffix (".csv").
// An output prefix (PREFIX.csv, PREFIX.json, ...) that names a device, FIFO or socket is refused: "--out
// /dev/null" would create /dev/null.csv beside the device, not discard the output.
inline CLI::Validator output_name() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (text.empty()) return "'' is empty: must be a file name or prefix";
        struct stat st {};
        if (::stat(text.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode))
          return "'" + text + "' is a device, FIFO or socket, and this flag takes a prefix (its files would be '" +
                 text + ".<suffix>'): give a file name prefix";
        return {};
      },
      "", "PATH");
}

// The items of a comma list as given ("-1,6"; several arguments of one flag read as one list, "1" "2" as "1,2"),
// empty items kept as "": CLI11's own splitting (->delimiter) drops them, which reads "1,,2" as "1,2".
inline std::vector<std::string> list_items(const std::vector<std::string>& args) {
  std::vector<std::string> items;
  for (const std::string& a : args)
    for (std::size_t start = 0;;) {
      const std::size_t comma = a.find(',', start);
      items.push_back(a.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  return items;
}
// Each item of a comma-list argument checked by `checks` in turn (number_text, integer_in, ...; the first
// message is reported); an empty item is refused.
inline CLI::Validator each_item(const std::vector<CLI::Validator>& checks, const std::string& what) {
  return CLI::Validator(
      [checks, what](std::string& text) -> std::string {
        for (std::string piece : list_items({text})) {
          if (piece.empty()) return "'" + text + "' has an empty item: must be " + what;
          for (const CLI::Validator& check : checks)
            if (std::string m = check(piece); !m.empty()) return m;
        }
        return {};
      },
      "", "LIST");
}
// The values of comma-list arguments that each_item(number_text(...)) or each_item(integer_in(...)) accepted.
inline std::vector<double> numbers_of(const std::vector<std::string>& args) {
  std::vector<double> out;
  for (const std::string& item : list_items(args)) out.push_back(read_number(item).value());
  return out;
}
inline std::vector<long long> integers_of(const std::vector<std::string>& args) {
  std::vector<long long> out;
  for (const std::string& item : list_items(args)) out.push_back(std::stoll(item));
  return out;
}

// --counts (diagram, report): a grid's nx and ny as "nx,ny", "NxM" or two values, each an integer in [1, 1000000].
inline const std::string kCountsForm = "two integers in [1, 1000000]: nx,ny or NxM";
inline std::vector<std::string> count_items(std::string text) {
  std::replace(text.begin(), text.end(), 'x', ',');
  return list_items({text});
}
inline void add_counts(CLI::App& app, std::vector<std::string>& counts, const std::string& help) {
  app.add_option("--counts", counts, help)
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            long long v = 0;
            for (const std::string& item : count_items(text))
              if (!parse_integer(item, v) || v < 1 || v > 1'000'000) return "'" + text + "' must be " + kCountsForm;
            return {};
          },
          "", "LIST"))
      ->expected(1, 2);
}
// The counts the --counts arguments give (none when not given); other than two throws InvalidArgument naming it.
inline std::vector<long long> counts_of(const std::vector<std::string>& args) {
  std::vector<long long> out;
  std::string given;
  for (const std::string& a : args) {
    for (const std::string& item : count_items(a)) out.push_back(std::stoll(item));
    given += (given.empty() ? "" : " ") + a;
  }
  if (!args.empty() && out.size() != 2)
    throw InvalidArgument("counts", "--counts = '" + given + "' must be " + kCountsForm);
  return out;
}

inline CLI::Validator positive() { return number_above(0, true); }
inline CLI::Validator non_negative() { return number_above(0, false); }

// Every numeric option of `app` and its subcommands that has no check of its own reads its whole text
// (number_text or integer_text, the option's description as the range): CLI11 alone reads "" as 0.
void require_whole_numbers(CLI::App& app);
// The standard message (flag, the values as given, what it accepts: the option's description) for CLI11's
// conversion failures and wrong value counts (a single-value flag given twice); "" for other parse errors,
// whose own messages already name the flag and value.
std::string parse_error_message(CLI::App& app, const CLI::ParseError& e);

}  // namespace rbcstab::cli
