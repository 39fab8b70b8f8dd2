#include "checks.hpp"

#include <algorithm>
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
}  // namespace

void require_whole_numbers(CLI::App& app) {
  for (CLI::Option* o : app.get_options()) {
    const std::string type = base_type(*o);
    const bool integer = type == "INT" || type == "UINT", number = type == "FLOAT";
    if (o->get_expected_max() == 0 || !(integer || number)) continue;
    if (has_check(*o, "NUMBER") || has_check(*o, "INT") || has_check(*o, "RANGE")) continue;
    o->check(integer ? integer_text(o->get_description()) : number_text(o->get_description()));
  }
  for (CLI::App* sub : subcommands(app)) require_whole_numbers(*sub);
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
    return name + ": given " + std::to_string(n) + " times (" + quoted_values(given) + "): must be given once" + accepts;
  const std::string wanted = lo == hi ? count_text(lo) : n < lo ? "at least " + count_text(lo) : "at most " + count_text(hi);
  return name + ": " + count_text(n) + " given (" + quoted_values(given) + "): takes " + wanted + accepts;
}

}  // namespace rbcstab::cli
