#include "rbcstab/core/text.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>

namespace rbcstab {
namespace {

class NanAsNa : public std::num_put<char> {
 protected:
  iter_type do_put(iter_type out, std::ios_base& io, char_type fill, double v) const override {
    return std::isnan(v) ? put_na(out, io, fill) : std::num_put<char>::do_put(out, io, fill, v);
  }
  iter_type do_put(iter_type out, std::ios_base& io, char_type fill, long double v) const override {
    return std::isnan(v) ? put_na(out, io, fill) : std::num_put<char>::do_put(out, io, fill, v);
  }

 private:
  static iter_type put_na(iter_type out, std::ios_base& io, char_type fill) {
    static constexpr std::string_view na = "n/a";
    const std::streamsize width = io.width(0);
    const std::size_t pad = width > std::streamsize(na.size()) ? std::size_t(width) - na.size() : 0;
    const bool left = (io.flags() & std::ios_base::adjustfield) == std::ios_base::left;
    if (!left) out = std::fill_n(out, pad, fill);
    out = std::copy(na.begin(), na.end(), out);
    if (left) out = std::fill_n(out, pad, fill);
    return out;
  }
};

}  // namespace

const std::locale& text_locale() {
  static const std::locale locale(std::locale::classic(), new NanAsNa);
  return locale;
}

namespace {
enum class Reading { number, not_a_number, beyond_range };
Reading read(const std::string& text, double& x) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  x = std::strtod(begin, &end);
  if (end == begin || end != begin + text.size()) return Reading::not_a_number;
  return errno == ERANGE && std::isinf(x) ? Reading::beyond_range : Reading::number;
}
}  // namespace

std::optional<double> read_number(const std::string& text) {
  double x = 0;
  return read(text, x) == Reading::number ? std::optional<double>(x) : std::nullopt;
}

std::optional<long long> read_integer(const std::string& text) {
  std::size_t pos = 0;
  long long v = 0;
  try {
    v = std::stoll(text, &pos);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  return pos != 0 && pos == text.size() ? std::optional<long long>(v) : std::nullopt;
}

std::vector<std::string> comma_items(const std::string& text) {
  std::vector<std::string> items;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    items.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return items;
    start = comma + 1;
  }
}

std::string number_error(const std::string& text) {
  double x = 0;
  return read(text, x) == Reading::beyond_range ? "'" + text + "' is out of range: beyond the largest double (1.8e308)"
                                                : "'" + text + "' is not a number";
}

}  // namespace rbcstab
