#pragma once
// index.html of the paper's folder (module-private; paper_page.cpp): every figure with its caption, its claims
// (measured, expected, verdict, how) and links to its data.
#include <nlohmann/json.hpp>
#include <string>

#include "rbcstab/report/paper.hpp"

namespace rbcstab::detail::paper {

// spec: the drawing spec (paper.json) of the figures drawn.
std::string paper_html(const nlohmann::json& spec, const PaperResult& r, const PaperOptions& o);

}  // namespace rbcstab::detail::paper
