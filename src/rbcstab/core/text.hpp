#pragma once
// Text outputs for people: a value that is not a number prints as "n/a", never "nan", so the text says
// "no value" in words and the line that gives the value's reason (a run's status, an input that overflows)
// can stand beside it; infinities stay "inf" (the vesicle limit's S = inf is a value). Machine outputs have
// their own rules: JSON null plus "<key>_reason", an empty CSV field (io/json.hpp).
#include <locale>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace rbcstab {

// The classic locale with NaN written as "n/a" (padded to the stream's width like any number).
const std::locale& text_locale();

// An output string stream in text_locale(): every *_text renderer writes into one.
class TextStream : public std::ostringstream {
 public:
  TextStream() { imbue(text_locale()); }
};

// How every number typed by a user is read (flags, l=value lists): the whole text as strtod reads it (decimal,
// hexadecimal, inf, nan); a value below the smallest normal double (1e-320) is its nearest double, as in a
// TOML scene. Nothing for an empty text, trailing characters or a value beyond the largest double (1e400).
std::optional<double> read_number(const std::string& text);
// The items of a comma list as given ("-1,6": "-1" and "6"), an empty one kept ("1,,2" has three): every list a
// user types (a flag's items, l=value modes, a range LO,HI) is split here, so an empty item is refused, not dropped.
std::vector<std::string> comma_items(const std::string& text);
// How every integer typed by a user is read: the whole text as std::stoll reads it; nothing for an empty text,
// trailing characters ("3.5", "1abc") or a value beyond long long.
std::optional<long long> read_integer(const std::string& text);
// Why read_number refused text: "'1e400' is out of range: beyond the largest double (1.8e308)" or "'abc' is not a
// number".
std::string number_error(const std::string& text);

}  // namespace rbcstab
