#pragma once
// README.md and index.html of a report folder, from its manifest (report.json) and the list of
// figures the plotting script drew (figures.json).
#include <nlohmann/json.hpp>
#include <string>

namespace rbcstab::detail {

std::string report_markdown(const nlohmann::json& manifest, const nlohmann::json& drawn);
std::string report_html(const nlohmann::json& manifest, const nlohmann::json& drawn);
// Text for HTML: < > & " escaped (every page the report module writes).
std::string html_escape(const std::string& s);

}  // namespace rbcstab::detail
