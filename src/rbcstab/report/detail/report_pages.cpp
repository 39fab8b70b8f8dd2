#include "rbcstab/report/detail/report_pages.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/report/detail/html_text.hpp"
#include "rbcstab/report/detail/provenance.hpp"

namespace rbcstab::detail {

namespace {
std::string num(const nlohmann::json& v, int digits = 6) {
  if (v.is_null()) return "n/a";
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  std::ostringstream ss;
  ss.precision(digits);
  ss << v.get<double>();
  return ss.str();
}

// One table: header and rows of plain text cells.
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

struct Page {
  std::string title, regime;
  std::vector<std::pair<std::string, Table>> tables;
  std::vector<std::string> warnings;
};

// Maths between $...$ (html_text: MathML on the page; plain_text: the README).
std::string regime_text(const nlohmann::json& m) {
  const auto& s = m.at("summary");
  std::ostringstream ss;
  const int lD = s.at("l_Delta").get<int>();
  ss << "Model level " << num(s.at("model")) << " (" << num(s.at("model_reason")) << "), run status "
     << num(s.at("status")) << " at $t$ = " << num(s.at("t_reached")) << ". ";
  if (lD == 2)
    ss << "No mode $l >= 3$ gained excess area: $l_Delta = 2$, the ellipsoidal dynamics are stable to the "
          "perturbations. ";
  else
    ss << "Shape instability: mode $l_Delta$ = " << lD << " gained the most excess area ("
       << (s.at("oscillating").get<bool>() ? "tail mean over the last window, oscillating run" : "at $t = T$") << "). ";
  const auto& th = m.at("thresholds");
  ss << "$alpha = B/C$ = " << num(th.at("alpha"))
     << ": the most dangerous continuous mode is $l_*$ = " << num(th.at("l_star"))
     << " with $sigma_* = -4 sqrt(alpha)$ = " << num(th.at("sigma_star"))
     << "; $sigma(T)$ = " << num(s.at("sigma_final")) << " (tail mean " << num(s.at("sigma_tail_mean")) << "). ";
  if (m.contains("reduced_summary")) {
    const auto& r = m.at("reduced_summary");
    ss << "Reduced system: $r(T)$ = " << num(r.at("r_final")) << ", $Psi(T)$ = " << num(r.at("Psi_final")) << ".";
  }
  return ss.str();
}

// The convergence check (report/convergence.hpp): each number, its change under each refinement, the tolerance
// and the flag; then the refined runs themselves.
void add_convergence(const nlohmann::json& c, Page& p, const std::string& what = "Convergence",
                     const std::string& note = "") {
  if (!c.at("checked").get<bool>()) {
    p.tables.push_back({"Convergence", {{"checked", "why"}, {{"no", c.at("reason").get<std::string>()}}}});
    return;
  }
  Table t{{"quantity", "value"}, {}};
  for (const auto& r : c.at("runs")) t.header.push_back("change " + r.at("refinement").get<std::string>());
  t.header.insert(t.header.end(), {"tolerance", "flag"});
  auto list = [](const nlohmann::json& a) {
    std::string s;
    for (const auto& x : a) s += (s.empty() ? "" : ", ") + x.get<std::string>();
    return s;
  };
  for (const auto& row : c.at("rows")) {
    std::vector<std::string> cells{row.at("quantity").get<std::string>(), num(row.at("value"))};
    for (const auto& r : c.at("runs"))
      cells.push_back(num(row.at("changes").at(r.at("refinement").get<std::string>()), 3));
    cells.push_back(num(row.at("tolerance"), 3));
    std::string flag = row.at("flagged").get<bool>() ? "" : "ok";
    if (!row.at("moved_by").empty()) flag = "MOVED by " + list(row.at("moved_by"));
    if (!row.at("not_shown_by").empty())
      flag +=
          (flag.empty() ? "" : "; ") + std::string("not shown: ") + list(row.at("not_shown_by")) + " did not finish";
    cells.push_back(flag);
    t.rows.push_back(cells);
  }
  p.tables.push_back({what + ": " + num(c.at("flagged")) + " of " + std::to_string(c.at("rows").size()) +
                          " numbers flagged. " + (note.empty() ? c.at("rule").get<std::string>() : note),
                      t});
  Table runs{{"refinement", "change", "status", "seconds"}, {}};
  for (const auto& r : c.at("runs"))
    runs.rows.push_back(
        {r.at("refinement").get<std::string>(), r.at("change").get<std::string>(),
         r.at("status").get<std::string>() +
             (r.at("reason").get<std::string>().empty() ? "" : ": " + r.at("reason").get<std::string>()),
         num(r.at("seconds"), 3)});
  p.tables.push_back({what + " runs (the scene again, one refinement each)", runs});
  if (c.contains("reduced_companion"))
    add_convergence(c.at("reduced_companion"), p, "Convergence of the reduced companion",
                    "The same rule; L + 2 and delta/10 do not apply (no l >= 3 modes, no seeds).");
}

Page make_page(const nlohmann::json& m) {
  Page p;
  const auto& sc = m.at("scene");
  const auto& par = m.at("parameters");
  const bool panel = m.contains("panel");
  p.title = (panel ? "rbcstab figure panel: scene " : "rbcstab report: scene ") + num(sc.at("name"));
  p.regime = panel ? m.at("panel").at("summary").get<std::string>() : regime_text(m);
  Table params{{"symbol", "value", "meaning"}, {}};
  auto row = [&](const char* k, const nlohmann::json& v, const char* meaning) {
    params.rows.push_back({k, num(v, 10), meaning});
  };
  // Every row of the parameter table the report's JSON holds: the material numbers and composites under
  // "parameters", the initial shape's under "scene".
  for (const ParameterRow& r : parameter_table()) {
    const nlohmann::json* v = par.contains(r.name) ? &par.at(r.name) : sc.contains(r.name) ? &sc.at(r.name) : nullptr;
    if (v && r.scale == AxisScale::linear) params.rows.push_back({r.unicode, num(*v, 10), r.description});
  }
  row("L", sc.at("L"), "truncation");
  row("T", sc.at("T"), "horizon");
  p.tables.push_back({panel ? "Base scene (the panel varies some of these)" : "Parameters", params});
  if (panel) {
    Table facts{{"quantity", "value"}, {}};
    for (const auto& f : m.at("panel").at("facts"))
      facts.rows.push_back({f.at(0).get<std::string>(), f.at(1).get<std::string>()});
    p.tables.push_back({"Panel", facts});
    for (const auto& t : m.at("panel").value("tables", nlohmann::json::array())) {
      Table more{t.at("header").get<std::vector<std::string>>(), {}};
      for (const auto& r : t.at("rows")) more.rows.push_back(r.get<std::vector<std::string>>());
      p.tables.push_back({t.at("title").get<std::string>(), more});
    }
    for (const auto& w : m.at("warnings")) p.warnings.push_back(w.get<std::string>());
    return p;
  }
  const auto& s = m.at("summary");

  Table modes{{"$l$", "$Delta_l(0)$", "$Delta_l(T)$", "tail mean", "$sigma_l^c$"}, {}};
  const auto& sigc = m.at("thresholds").at("sigma_c");
  // Numeric order (JSON object keys sort as strings: "10" < "2").
  const auto& init = s.at("excess_area_initial");
  for (int l = 2; init.contains(std::to_string(l)); ++l) {
    const std::string k = std::to_string(l);
    modes.rows.push_back({k, num(init.at(k)), num(s.at("excess_area_final").at(k)),
                          num(s.at("excess_area_tail_mean").at(k)), sigc.contains(k) ? num(sigc.at(k)) : "n/a"});
  }
  p.tables.push_back({"Excess area per mode (mode $l$ grows while $sigma < sigma_l^c$)", modes});

  Table run{{"quantity", "value"}, {}};
  for (const char* k :
       {"status", "l_Delta", "l_Delta_final", "oscillating", "sigma_initial", "sigma_final", "sigma_tail_mean",
        "r_final", "Psi_final", "excess_area_drift", "steps", "rhs_evaluations", "seconds"})
    run.rows.push_back({k, num(s.at(k))});
  run.rows.push_back(
      {"shape rho_min / rho_max at T", num(m.at("shape").at("rho_min")) + " / " + num(m.at("shape").at("rho_max"))});
  p.tables.push_back({"Run", run});
  if (m.contains("physical")) {
    Table cell{{"quantity", "value"}, {}};
    for (const auto& [k, v] : m.at("physical").items()) cell.rows.push_back({k, num(v)});
    p.tables.push_back({"Physical cell (SI; model times are in units of 1/gamma = time_unit_s)", cell});
  }
  if (m.contains("shear_rate_thresholds")) {
    Table rates{{"orientation", "first unstable shear rate [1/s]", "mode l", "shape", "B, C there"}, {}};
    for (const auto& t : m.at("shear_rate_thresholds")) {
      const bool found = t.value("found", false);
      rates.rows.push_back({t.value("orientation", ""),
                            found ? num(t.at("shear_rate")) : "not found: " + t.value("reason", ""),
                            t.contains("l") ? num(t.at("l")) : "", t.value("shape", ""),
                            found ? num(t.at("B")) + ", " + num(t.at("C")) : ""});
    }
    p.tables.push_back(
        {"Shear-rate thresholds (asymptotic verdict along B, C proportional to gamma at fixed alpha)", rates});
  }
  if (m.contains("convergence")) add_convergence(m.at("convergence"), p);
  for (const auto& w : m.at("warnings")) p.warnings.push_back(w.get<std::string>());
  return p;
}

const nlohmann::json* figure_of(const nlohmann::json& m, const std::string& png) {
  for (const auto& f : m.at("figures"))
    if (f.at("png") == png) return &f;
  return nullptr;
}

const char* kShapeFiles = "shape_T.vtk (VTK legacy), shape_T.vtp (VTK XML PolyData), shape_T.ply, shape_T.csv (grid)";
}  // namespace

std::string page_head_html(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + html_escape(title) +
         "</title>\n<style>body{font-family:sans-serif;max-width:70em;margin:auto;padding:1em}"
         "table{border-collapse:collapse;margin:0.5em 0}td,th{border:1px solid #999;padding:2px 8px;text-align:right}"
         "figure{margin:1.5em 0}img{max-width:100%;border:1px solid #ddd}.warn{color:#a00}"
         ".hover-tip{position:fixed;background:#fff;border:1px solid #666;padding:2px 6px;font-size:0.85em;"
         "pointer-events:none}</style></head><body>\n";
}

std::string table_markdown(const std::string& title, const std::vector<std::string>& header,
                           const std::vector<std::vector<std::string>>& rows) {
  std::ostringstream md;
  md << "## " << plain_text(title) << "\n\n|";
  for (const auto& h : header) md << ' ' << plain_text(h) << " |";
  md << "\n|";
  for (std::size_t k = 0; k < header.size(); ++k) md << " --- |";
  md << "\n";
  for (const auto& r : rows) {
    md << "|";
    for (const auto& c : r) md << ' ' << plain_text(c) << " |";
    md << "\n";
  }
  md << "\n";
  return md.str();
}

std::string table_html(const std::string& title, const std::vector<std::string>& header,
                       const std::vector<std::vector<std::string>>& rows) {
  std::ostringstream h;
  h << "<h2>" << html_text(title) << "</h2>\n<table><tr>";
  for (const auto& c : header) h << "<th>" << html_text(c) << "</th>";
  h << "</tr>\n";
  for (const auto& r : rows) {
    h << "<tr>";
    for (const auto& c : r) h << "<td>" << html_text(c) << "</td>";
    h << "</tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '&':
        o += "&amp;";
        break;
      case '"':
        o += "&quot;";
        break;
      default:
        o += c;
    }
  }
  return o;
}

namespace {
// JSON inside <script>: "</" written "<\/" so that no string in it can close the element.
std::string script_json(const nlohmann::json& j) {
  std::string s = j.dump();
  for (std::size_t k = s.find("</"); k != std::string::npos; k = s.find("</", k + 3)) s.insert(k + 1, "\\");
  return s;
}

// The stamp of a manifest that carries one (every report written since it was added), else nothing.
std::string provenance_footer_html(const nlohmann::json& m) {
  return m.contains("provenance") ? provenance_html(provenance_from_json(m.at("provenance"))) : "";
}
std::string provenance_footer_markdown(const nlohmann::json& m) {
  return m.contains("provenance") ? "\n" + provenance_markdown(provenance_from_json(m.at("provenance"))) : "";
}
}  // namespace

std::string report_markdown(const nlohmann::json& m, const nlohmann::json& drawn) {
  const Page p = make_page(m);
  std::ostringstream md;
  md << "# " << p.title << "\n\n" << plain_text(p.regime) << "\n\n";
  for (const auto& w : p.warnings) md << "> warning: " << plain_text(w) << "\n\n";
  for (const auto& [title, t] : p.tables) md << table_markdown(title, t.header, t.rows);
  md << "## Figures\n\n";
  for (const auto& d : drawn) {
    const std::string file = d.at("file");
    const nlohmann::json* f = figure_of(m, file);
    if (!f) continue;
    md << "### " << f->at("kind").get<std::string>() << "\n\n![" << file << "](" << file << ")\n\n"
       << plain_text(f->at("caption").get<std::string>()) << ". Data: ";
    bool first = true;
    for (const auto& x : f->at("data")) {
      md << (first ? "" : ", ") << "[" << x.get<std::string>() << "](" << x.get<std::string>() << ")";
      first = false;
    }
    if (f->contains("gif"))
      md << ". Animation: [" << f->at("gif").get<std::string>() << "](" << f->at("gif").get<std::string>() << ")";
    md << ".\n\n";
  }
  if (m.contains("panel")) {
    md << "## Reproduce\n\n```\nrbcstab report --scene scene.toml --output DIR\n```\n\nThe numbers are in report.json "
       << "(manifest) and the data files beside each figure.\n"
       << provenance_footer_markdown(m);
    return md.str();
  }
  md << "## Shape files\n\n" << kShapeFiles << ": open the .vtk or .vtp in ParaView, colour by `rho`.\n\n";
  md << "## Reproduce\n\n```\nrbcstab report --scene scene.toml --output "
     << "DIR\n```\n\n"
     << "The numbers above are in report.json (manifest), trajectory.csv (t, Delta_2..Delta_L, sigma, r, Psi) and "
     << "thresholds.json.\n"
     << provenance_footer_markdown(m);
  return md.str();
}

std::string report_html(const nlohmann::json& m, const nlohmann::json& drawn) {
  const Page p = make_page(m);
  std::ostringstream h;
  h << page_head_html(p.title);
  h << "<h1>" << html_escape(p.title) << "</h1>\n<p>" << html_text(p.regime) << "</p>\n";
  for (const auto& w : p.warnings) h << "<p class=\"warn\">warning: " << html_text(w) << "</p>\n";
  for (const auto& [title, t] : p.tables) h << table_html(title, t.header, t.rows);
  h << "<h2>Figures</h2>\n";
  std::string data_scripts;  // the values behind the figures that show them on hover, and the script, at the end
  for (const auto& d : drawn) {
    const std::string file = d.at("file");
    const nlohmann::json* f = figure_of(m, file);
    if (!f) continue;
    // A click opens the figure whole: its SVG where there is one (it scales without blur), else the PNG.
    const std::string whole = d.contains("svg") ? d.at("svg").get<std::string>() : file;
    std::string hover;
    if (d.contains("hover")) {
      const std::string id = "hover-" + std::to_string(data_scripts.size());
      hover = " data-hover=\"" + id + "\"";
      data_scripts +=
          "<script type=\"application/json\" id=\"" + id + "\">" + script_json(d.at("hover")) + "</script>\n";
    }
    h << "<figure><a href=\"" << html_escape(whole) << "\" title=\"open the figure whole\"><img src=\""
      << html_escape(file) << "\" alt=\"" << html_escape(f->at("kind").get<std::string>()) << "\"" << hover
      << "></a><figcaption>" << html_text(f->at("caption").get<std::string>()) << ". Data:";
    for (const auto& x : f->at("data"))
      h << " <a href=\"" << html_escape(x.get<std::string>()) << "\">" << html_escape(x.get<std::string>()) << "</a>";
    if (f->contains("gif"))
      h << ". Animation: <a href=\"" << html_escape(f->at("gif").get<std::string>()) << "\">"
        << html_escape(f->at("gif").get<std::string>()) << "</a>";
    h << (hover.empty() ? "" : ". Values on hover: the nearest point's") << ".</figcaption></figure>\n";
  }
  if (!data_scripts.empty()) data_scripts += std::string("<script>") + hover_script() + "</script>\n";
  if (m.contains("panel")) {
    h << "<h2>Reproduce</h2>\n<pre>rbcstab report --scene scene.toml --output DIR</pre>\n"
      << "<p>Numbers: <a href=\"report.json\">report.json</a> and the data files beside each "
         "figure.</p>\n"
      << provenance_footer_html(m) << data_scripts << "</body></html>\n";
    return h.str();
  }
  h << "<h2>Shape files</h2>\n<p>" << html_escape(kShapeFiles)
    << ": open the .vtk or .vtp in ParaView, colour by <code>rho</code>.</p>\n"
    << "<h2>Reproduce</h2>\n<pre>rbcstab report --scene scene.toml --output DIR</pre>\n"
    << "<p>Numbers: <a href=\"report.json\">report.json</a>, <a href=\"trajectory.csv\">trajectory.csv</a>, "
       "<a href=\"thresholds.json\">thresholds.json</a>.</p>\n"
    << provenance_footer_html(m) << data_scripts << "</body></html>\n";
  return h.str();
}

}  // namespace rbcstab::detail
