// The paper's page, index.html: each figure with its PNG and caption, the table of its claims and its data files.
#include "rbcstab/report/detail/paper_page.hpp"

#include <sstream>

#include "rbcstab/report/detail/html_text.hpp"
#include "rbcstab/report/detail/paper_composer.hpp"
#include "rbcstab/report/detail/provenance.hpp"
#include "rbcstab/report/detail/report_pages.hpp"

namespace rbcstab::detail::paper {

namespace {

std::string esc(const std::string& s) { return html_escape(s); }

}  // namespace

std::string paper_html(const json& spec, const PaperResult& r, const PaperOptions& o) {
  std::ostringstream h;
  h << "<!doctype html><html><head><meta charset=\"utf-8\"><title>rbcstab: the paper's figures</title><style>"
       "body{font-family:sans-serif;max-width:1400px;margin:auto;padding:1em}"
       "table{border-collapse:collapse;font-size:0.9em}td,th{border:1px solid #ccc;padding:3px 6px;vertical-align:top}"
       ".pass{background:#e6f4e6}.fail{background:#fbe3e3}img{max-width:100%;border:1px solid #ddd}"
       ".fig{display:flex;gap:1em;flex-wrap:wrap}.fig>div{flex:1 1 600px}</style></head><body>\n";
  h << "<h1>Moriel, Stone &amp; Mendez: the figures recomputed by rbcstab</h1>\n<p>"
    << (o.quick ? "Quick mode (coarse grids: 12 x 12 phase diagrams, a reduced Fig. 6e grid). " : "Full grids. ")
    << "Claims checked: " << r.passed << " passed, " << r.failed << " failed (" << r.inconsistent
    << " of them paper/model inconsistencies: the model run as the paper states contradicts the paper; the evidence "
       "is in the row). Runs that did not reach T: "
    << r.failed_runs << ". A failed claim is shown as measured, not tuned away.</p>\n<ul>";
  for (const auto& f : spec["figures"])
    h << "<li><a href=\"#" << f["id"].get<std::string>() << "\">" << html_text(f["title"].get<std::string>())
      << "</a></li>";
  h << "</ul>\n";
  for (const auto& f : spec["figures"]) {
    const std::string label = f["label"];
    h << "<h2 id=\"" << f["id"].get<std::string>() << "\">" << html_text(f["title"].get<std::string>()) << "</h2>\n"
      << "<div class=\"fig\"><div><a href=\"" << esc(f.value("svg", f["png"].get<std::string>()))
      << "\" title=\"open the figure whole\"><img src=\"" << esc(f["png"].get<std::string>()) << "\" alt=\""
      << esc(label) << "\"></a></div><div><p>" << html_text(f["caption"].get<std::string>())
      << "</p>\n<table><tr><th>claim</th><th>measured</th>"
      << "<th>expected</th><th></th><th>how</th></tr>\n";
    for (const ClaimCheck& c : r.claims)
      if (c.figure == label)
        h << "<tr class=\"" << (c.passed ? "pass" : "fail") << "\"><td>" << html_text(c.claim) << "</td><td>"
          << html_text(c.measured) << "</td><td>" << html_text(c.expected) << "</td><td>"
          << (c.passed ? "passed" : "<b>FAILED</b>") << (c.inconsistency.empty() ? "" : " (paper/model inconsistency)")
          << "</td><td>" << html_text(c.how)
          << (c.inconsistency.empty() ? "" : "<br><b>Paper/model inconsistency:</b> " + html_text(c.inconsistency))
          << " <small>[check: " << esc(c.check) << "]</small></td></tr>\n";
    h << "</table><p>Data: ";
    for (const auto& d : f["data"])
      h << "<a href=\"" << d.get<std::string>() << "\">" << d.get<std::string>() << "</a> ";
    h << "</p><p>Computed in " << num(f["seconds"].get<double>(), 3) << " s.</p></div></div>\n";
  }
  h << "<p>Drawing spec: <a href=\"paper.json\">paper.json</a>; claims: <a href=\"claims.json\">claims.json</a>.</p>\n"
    << provenance_html(provenance_from_json(spec.at("provenance"))) << "</body></html>\n";
  return h.str();
}

}  // namespace rbcstab::detail::paper
