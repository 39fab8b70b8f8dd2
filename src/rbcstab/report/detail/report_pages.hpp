#pragma once
// README.md and index.html of a report folder, from its manifest (report.json) and the list of
// figures the plotting script drew (figures.json).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rbcstab::detail {

std::string report_markdown(const nlohmann::json& manifest, const nlohmann::json& drawn);
std::string report_html(const nlohmann::json& manifest, const nlohmann::json& drawn);
// Text for HTML: < > & " escaped (every page the report module writes).
std::string html_escape(const std::string& s);
// The pages' pieces: the head and opening body with the report's style; one titled table of text cells (maths
// between $...$) as a Markdown section or as HTML.
std::string page_head_html(const std::string& title);
std::string table_markdown(const std::string& title, const std::vector<std::string>& header,
                           const std::vector<std::vector<std::string>>& rows);
std::string table_html(const std::string& title, const std::vector<std::string>& header,
                       const std::vector<std::vector<std::string>>& rows);

}  // namespace rbcstab::detail
