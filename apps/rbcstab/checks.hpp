#pragma once
// Range checks for numeric flags whose messages read like the library's ("--step: -1 must be > 0").
// (CLI11's PositiveNumber prints its bound as the 300-digit DBL_MAX.)
#include <CLI/CLI.hpp>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/sweep/diagram_table.hpp"

namespace rbcstab::cli {

// Any number given in full, so that CLI11's own conversion (which reads "" as 0) never sees bad text;
// `range` says what the flag accepts (the library checks it after the scene is assembled).
inline CLI::Validator number_text(const std::string& range) {
  return CLI::Validator(
      [range](std::string& text) -> std::string {
        return read_number(text) ? "" : number_error(text) + " (" + range + ")";
      },
      "", "NUMBER");
}

// An integer given in full; `range` says what the flag accepts (checked by the library).
inline CLI::Validator integer_text(const std::string& range) {
  return CLI::Validator(
      [range](std::string& text) -> std::string {
        return read_integer(text) ? "" : "'" + text + "' is not an integer (" + range + ")";
      },
      "", "INT");
}

// An integer given in full, within [lo, hi].
inline CLI::Validator integer_in(long long lo, long long hi) {
  const std::string range = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        const std::optional<long long> v = read_integer(text);
        if (!v) return "'" + text + "' is not an integer (must be " + range + ")";
        if (*v < lo || *v > hi) return text + " is out of range: must be " + range;
        return {};
      },
      range, "INT");
}

// An integer option in [lo, hi] with its default shown: the range is checked and written once, into the help
// ("<help>, an integer in [lo, hi]<note>").
template <class T>
CLI::Option* add_integer(CLI::App& app, const std::string& flag, T& value, long long lo, long long hi,
                         const std::string& help, const std::string& note = "") {
  const std::string range = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return app.add_option(flag, value, help + ", " + range + note)->check(integer_in(lo, hi))->capture_default_str();
}

// Finite numbers above `bound` (strict) or at least `bound`.
inline CLI::Validator number_above(double bound, bool strict) {
  const std::string range = (strict ? "> " : ">= ") + CLI::detail::to_string(bound);
  return CLI::Validator(
      [bound, strict, range](std::string& text) -> std::string {
        const std::optional<double> v = read_number(text);
        if (!v) return number_error(text) + " (must be " + range + ")";
        if (!std::isfinite(*v) || (strict ? !(*v > bound) : !(*v >= bound)))
          return text + " is out of range: must be finite and " + range;
        return {};
      },
      range, "RANGE");
}
// A file name or prefix (io/files.hpp output_prefix_problem).
inline CLI::Validator output_name() {
  return CLI::Validator([](std::string& text) { return output_prefix_problem(text); }, "", "PATH");
}

// The items of a comma list as given ("-1,6"; several arguments of one flag read as one list, "1" "2" as "1,2"),
// empty items kept as "": CLI11's own splitting (->delimiter) drops them, which reads "1,,2" as "1,2".
inline std::vector<std::string> list_items(const std::vector<std::string>& args) {
  std::vector<std::string> items;
  for (const std::string& a : args)
    for (std::string& item : comma_items(a)) items.push_back(std::move(item));
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
// The values of comma-list arguments that each_item(number_text(...)) accepted.
inline std::vector<double> numbers_of(const std::vector<std::string>& args) {
  std::vector<double> out;
  for (const std::string& item : list_items(args)) out.push_back(read_number(item).value());
  return out;
}

// --counts (diagram, report): a grid's nx,ny as the library reads them (parse_counts: nx,ny, NxM or two values).
inline void add_counts(CLI::App& app, std::vector<std::string>& counts, const std::string& help) {
  app.add_option("--counts", counts, help)->expected(1, 2);
}
inline std::vector<long long> counts_of(const std::vector<std::string>& args) {
  return args.empty() ? std::vector<long long>{} : parse_counts(args, "--counts");
}

inline CLI::Validator positive() { return number_above(0, true); }
inline CLI::Validator non_negative() { return number_above(0, false); }

// Every numeric option of `app` reads its whole text: a check naming its range first (its own, or number_text or
// integer_text with the option's description: CLI11 alone reads "" as 0), then the text handed to CLI11 is one it
// reads as rbcstab does ("010" is 10, not octal 8; a decimal is read once, not through long double).
void read_numbers_whole(CLI::App& app);
// The standard message (flag, the values as given, what it accepts: the option's description) for CLI11's
// conversion failures and wrong value counts (a single-value flag given twice); "" for other parse errors,
// whose own messages already name the flag and value.
std::string parse_error_message(CLI::App& app, const CLI::ParseError& e);

}  // namespace rbcstab::cli
