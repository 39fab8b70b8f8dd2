#include "checks.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace rbcstab::cli {

namespace {
// CLI11's type name without the validators' descriptions ("INT:an integer in [0, 4096]" -> "INT").
std::string base_type(const CLI::Option& o) {
  const std::string t = o.get_type_name();
  return t.substr(0, t.find(':'));
}

bool has_check(CLI::Option& o, const std::string& name) {
  try {
    o.get_validator(name);
    return true;
  } catch (const CLI::OptionNotFound&) {
    return false;
  }
}

// Every subcommand, parsed or not.
std::vector<CLI::App*> subcommands(CLI::App& app) {
  return app.get_subcommands([](CLI::App*) { return true; });
}

// The option named `name` (as CLI11's messages name it) that received values: of app or of the subcommand
// being parsed (other subcommands have options of the same name); nullptr if none.
CLI::Option* find_option(CLI::App& app, const std::string& name) {
  for (CLI::Option* o : app.get_options())
    if (o->get_name() == name && !o->results().empty()) return o;
  for (CLI::App* sub : subcommands(app))
    if (CLI::Option* o = find_option(*sub, name)) return o;
  return nullptr;
}

std::string quoted_values(const std::vector<std::string>& values) {
  std::string t;
  for (const std::string& v : values) t += (t.empty() ? "'" : ", '") + v + "'";
  return t;
}

std::string count_text(int n) { return n == 1 ? "one value" : std::to_string(n) + " values"; }

// The text CLI11 converts for a numeric option, made from rbcstab's own reading of the whole text: CLI11 alone
// reads "" as 0, "010" as octal 8, "0x10" as 16, "-1" for an unsigned option as 2^64 - 1, and a decimal through
// long double (rounded twice). Integers become plain decimal, other numbers hexadecimal floats (read exactly).
CLI::Validator whole_number(const std::string& type) {
  return CLI::Validator(
      [type](std::string& text) -> std::string {
        if (type == "FLOAT") {
          const std::optional<double> v = read_number(text);
          if (!v) return number_error(text);
          // Rewritten only when CLI11's reading would differ, so that messages quote the value as given.
          if (static_cast<double>(std::strtold(text.c_str(), nullptr)) != *v) {
            char hex[64];
            std::snprintf(hex, sizeof hex, "%a", *v);
            text = hex;
          }
          return {};
        }
        const std::optional<long long> v = read_integer(text);
        if (!v) return "'" + text + "' is not an integer";
        if (type == "UINT" && *v < 0) return text + " is out of range: must be an integer >= 0";
        text = std::to_string(*v);
        return {};
      },
      "", "");
}
}  // namespace

void read_numbers_whole(CLI::App& app) {
  for (CLI::Option* o : app.get_options()) {
    const std::string type = base_type(*o);
    const bool integer = type == "INT" || type == "UINT";
    if (!integer && type != "FLOAT") continue;
    if (o->get_expected_max() != 0 && !has_check(*o, "NUMBER") && !has_check(*o, "INT") && !has_check(*o, "RANGE"))
      o->check(integer ? integer_text(o->get_description()) : number_text(o->get_description()));
    o->check(whole_number(type), "whole_number");
    o->get_validator("whole_number")->non_modifying(false);  // check() adds a validator that cannot rewrite the text
  }
}

std::string parse_error_message(CLI::App& app, const CLI::ParseError& e) {
  const std::string what = e.what();
  std::string name;
  const bool conversion = dynamic_cast<const CLI::ConversionError*>(&e) != nullptr;
  if (conversion) {
    const std::string lead = "Could not convert: ";
    const auto eq = what.find(" = ");
    if (what.rfind(lead, 0) != 0 || eq == std::string::npos) return "";
    name = what.substr(lead.size(), eq - lead.size());
  } else if (dynamic_cast<const CLI::ArgumentMismatch*>(&e)) {
    name = what.substr(0, what.find(':'));
  } else {
    return "";
  }
  CLI::Option* o = find_option(app, name);
  if (!o) return "";
  const std::string accepts = " (" + o->get_description() + ")";
  const std::vector<std::string>& given = o->results();
  if (conversion) {
    const std::string type = base_type(*o);
    const std::string kind = type == "INT" || type == "UINT" ? "an integer of this range" : "a valid value";
    return name + ": " + quoted_values(given) + " is not " + kind + accepts;
  }
  const int lo = std::max(o->get_items_expected_min(), 1), hi = std::max(o->get_items_expected_max(), 1);
  const int n = int(given.size());
  if (n > hi && hi == 1)
    return name + ": given " + std::to_string(n) + " times (" + quoted_values(given) + "): must be given once" +
           accepts;
  const std::string wanted = lo == hi ? count_text(lo)
                             : n < lo ? "at least " + count_text(lo)
                                      : "at most " + count_text(hi);
  return name + ": " + count_text(n) + " given (" + quoted_values(given) + "): takes " + wanted + accepts;
}

}  // namespace rbcstab::cli
