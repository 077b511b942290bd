#include "reproduce/report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/atomic_file.hpp"

namespace granule::reproduce {

namespace fs = std::filesystem;

namespace {

// A number as the tables show it: 4 significant digits, "—" when missing.
std::string number(double x) { return std::isfinite(x) ? fmt::format("{:.4g}", x) : "—"; }

std::string measured_text(const Claim& c) {
  if (!std::isfinite(c.measured)) return "—";
  // The error to two digits: its own uncertainty is larger than that.
  return std::isfinite(c.error) ? fmt::format("{} ± {:.2g}", number(c.measured), c.error) : number(c.measured);
}

// What the verdict rests on: why it cannot be decided (the study's reason or the rule's), and how it was measured.
std::string basis(const Claim& c) {
  const std::string reason = judgement(c).reason;
  return reason.empty() ? c.checked : reason + ". " + c.checked;
}

std::string html_escape(const std::string& text) {
  std::string out;
  for (char ch : text) {
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += ch;
    }
  }
  return out;
}

std::string markdown_cell(const std::string& text) {
  std::string out;
  for (char ch : text) out += ch == '|' ? std::string("\\|") : std::string(1, ch);
  return out;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char ch : text) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

struct Tally {
  int agrees = 0, disagrees = 0, unresolvable = 0;
};

Tally tally(const Report& report) {
  Tally t;
  for (const StudySection& s : report.sections) {
    for (const Claim& c : s.outcome.claims) {
      switch (judge(c)) {
        case Verdict::agrees:
          ++t.agrees;
          break;
        case Verdict::disagrees:
          ++t.disagrees;
          break;
        case Verdict::not_resolvable:
          ++t.unresolvable;
          break;
      }
    }
  }
  return t;
}

std::string tally_text(const Report& report) {
  const Tally t = tally(report);
  return fmt::format("{} claims: {} agree, {} disagree, {} not resolvable at this scale", t.agrees + t.disagrees + t.unresolvable,
                     t.agrees, t.disagrees, t.unresolvable);
}

std::string time_text(const Report& report) {
  return fmt::format("this call took {:.0f} s of wall time; the runs took {:.0f} s in all (summed over runs)",
                     report.wall_seconds, report.run_seconds);
}

const char* kColumns[] = {"claim", "where", "expected", "Granule", "tolerance", "why this tolerance", "verdict", "checked"};

std::vector<std::string> claim_cells(const Claim& c) {
  return {c.statement,       c.location,         number(c.expected),     measured_text(c),
          tolerance_text(c), c.tolerance_reason, verdict_text(judge(c)), basis(c)};
}

std::string markdown(const Report& report) {
  std::string md = fmt::format(
      "# Granule reproduces Tan (1995): report\n\nScale `{}`; {}.\n\n"
      "Repeat with `{}` (finished runs are skipped).\n\n**{}.**\n",
      report.scale, time_text(report), report.command, tally_text(report));
  for (const StudySection& s : report.sections) {
    md += fmt::format("\n## {} — {}\n\n{}\n\n", s.study->name, s.study->title, s.study->thesis_part);
    for (const std::string& line : s.run_lines) md += fmt::format("- runs: {}\n", line);
    for (const std::string& note : s.outcome.notes) md += fmt::format("- note: {}\n", note);
    md += "\n|";
    for (const char* column : kColumns) md += fmt::format(" {} |", column);
    md += "\n|";
    for (std::size_t k = 0; k < std::size(kColumns); ++k) md += "---|";
    md += "\n";
    for (const Claim& c : s.outcome.claims) {
      md += "|";
      for (const std::string& cell : claim_cells(c)) md += fmt::format(" {} |", markdown_cell(cell));
      md += "\n";
    }
    for (const Figure& f : s.outcome.figures) {
      md += fmt::format("\n![{0}](figures/{1}.png)\n\n*{2}* — {0}\n", f.caption, f.name, f.thesis_figure);
    }
  }
  return md;
}

constexpr const char* kStyle =
    R"(body{font-family:sans-serif;max-width:1150px;margin:2em auto;padding:0 1em;color:#222;line-height:1.4}
table{border-collapse:collapse;width:100%;font-size:0.85em;margin:1em 0}th,td{border:1px solid #ccc;padding:4px 6px;vertical-align:top;text-align:left}
th{background:#f0f0f0}td.num{white-space:nowrap}tr.agrees td.verdict{background:#d8f0d8}tr.disagrees td.verdict{background:#f6d0d0}
tr.not-resolvable td.verdict{background:#eee}figure{margin:1.5em 0;text-align:center}figure img{max-width:760px;width:100%}
figcaption{font-size:0.9em;color:#444}.summary{font-size:1.1em;font-weight:bold}code{background:#f4f4f4})";

std::string verdict_class(Verdict v) {
  switch (v) {
    case Verdict::agrees:
      return "agrees";
    case Verdict::disagrees:
      return "disagrees";
    case Verdict::not_resolvable:
      return "not-resolvable";
  }
  return "";
}

std::string html(const fs::path& dir, const Report& report) {
  std::string page = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Granule reproduces Tan (1995)</title>"
      "<style>{}</style></head><body>\n<h1>Granule reproduces Tan (1995)</h1>\n<p>Scale <code>{}</code>; {}. "
      "Repeat with <code>{}</code>. Every verdict follows from the numbers in its row (docs/reproduce.md).</p>\n"
      "<p class=\"summary\">{}.</p>\n",
      kStyle, html_escape(report.scale), html_escape(time_text(report)), html_escape(report.command),
      html_escape(tally_text(report)));
  for (const StudySection& s : report.sections) {
    page += fmt::format("<h2>{} — {}</h2>\n<p>{}</p>\n", html_escape(s.study->name), html_escape(s.study->title),
                        html_escape(s.study->thesis_part));
    page += "<ul>";
    for (const std::string& line : s.run_lines) page += "<li>runs: " + html_escape(line) + "</li>";
    for (const std::string& note : s.outcome.notes) page += "<li>note: " + html_escape(note) + "</li>";
    page += "</ul>\n<table><tr>";
    for (const char* column : kColumns) page += fmt::format("<th>{}</th>", column);
    page += "</tr>\n";
    for (const Claim& c : s.outcome.claims) {
      const std::vector<std::string> cells = claim_cells(c);
      page += fmt::format("<tr class=\"{}\">", verdict_class(judge(c)));
      for (std::size_t k = 0; k < cells.size(); ++k) {
        const char* kind = k == 6 ? " class=\"verdict\"" : (k >= 2 && k <= 4 ? " class=\"num\"" : "");
        page += fmt::format("<td{}>{}</td>", kind, html_escape(cells[k]));
      }
      page += "</tr>\n";
    }
    page += "</table>\n";
    for (const Figure& f : s.outcome.figures) {
      const fs::path picture = dir / "figures" / (f.name + ".png");
      const std::string image = fs::exists(picture) ? fmt::format("<img alt=\"{}\" src=\"data:image/png;base64,{}\">",
                                                                  html_escape(f.caption), base64(read_bytes(picture)))
                                                    : "<p>(not drawn)</p>";
      page += fmt::format("<figure>{}<figcaption><b>{}</b> — {}</figcaption></figure>\n", image, html_escape(f.thesis_figure),
                          html_escape(f.caption));
    }
  }
  return page + "</body></html>\n";
}

std::string claims_csv(const Report& report) {
  std::string csv =
      "study,id,statement,location,expected,measured,error,tolerance,tolerance_kind,tolerance_reason,verdict,checked,"
      "unresolvable,verdict_reason\n";
  for (const StudySection& s : report.sections) {
    for (const Claim& c : s.outcome.claims) {
      const std::vector<std::string> fields{s.study->name,
                                            c.id,
                                            c.statement,
                                            c.location,
                                            fmt::format("{:.17g}", c.expected),
                                            fmt::format("{:.17g}", c.measured),
                                            fmt::format("{:.17g}", c.error),
                                            fmt::format("{:.17g}", c.tolerance),
                                            tolerance_kind_name(c.tolerance_kind),
                                            c.tolerance_reason,
                                            verdict_text(judge(c)),
                                            c.checked,
                                            c.unresolvable,
                                            judgement(c).reason};
      for (std::size_t k = 0; k < fields.size(); ++k) csv += fmt::format("{}{}", k > 0 ? "," : "", csv_field(fields[k]));
      csv += "\n";
    }
  }
  return csv;
}

nlohmann::json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

std::string claims_json(const Report& report) {
  nlohmann::json j = {{"scale", report.scale},
                      {"command", report.command},
                      {"wall_seconds", report.wall_seconds},
                      {"run_seconds", report.run_seconds}};
  nlohmann::json studies = nlohmann::json::array();
  for (const StudySection& s : report.sections) {
    nlohmann::json claims = nlohmann::json::array();
    for (const Claim& c : s.outcome.claims) {
      claims.push_back({{"id", c.id},
                        {"statement", c.statement},
                        {"location", c.location},
                        {"expected", finite_or_null(c.expected)},
                        {"measured", finite_or_null(c.measured)},
                        {"error", finite_or_null(c.error)},
                        {"tolerance", c.tolerance},
                        {"tolerance_kind", tolerance_kind_name(c.tolerance_kind)},
                        {"tolerance_reason", c.tolerance_reason},
                        {"verdict", verdict_text(judge(c))},
                        {"checked", c.checked},
                        {"unresolvable", c.unresolvable},
                        {"verdict_reason", judgement(c).reason}});
    }
    studies.push_back({{"name", s.study->name},
                       {"title", s.study->title},
                       {"claims", claims}});
  }
  j["studies"] = studies;
  return j.dump(2) + "\n";
}

}  // namespace

std::string figure_json(const Figure& f) {
  nlohmann::json series = nlohmann::json::array();
  for (const FigureSeries& s : f.series) {
    series.push_back({{"label", s.label}, {"x", s.x}, {"y", s.y}, {"error", s.error}, {"line", s.line}});
  }
  const nlohmann::json figure = {{"title", f.thesis_figure}, {"x_label", f.x_label}, {"y_label", f.y_label},
                                 {"log_x", f.log_x},         {"log_y", f.log_y},     {"series", series}};
  return figure.dump() + "\n";
}

std::string base64(const std::string& bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t left = bytes.size() - i;
    const unsigned a = static_cast<unsigned char>(bytes[i]);
    const unsigned b = left > 1 ? static_cast<unsigned char>(bytes[i + 1]) : 0u;
    const unsigned c = left > 2 ? static_cast<unsigned char>(bytes[i + 2]) : 0u;
    const unsigned triple = (a << 16) | (b << 8) | c;
    out += kAlphabet[(triple >> 18) & 63];
    out += kAlphabet[(triple >> 12) & 63];
    out += left > 1 ? kAlphabet[(triple >> 6) & 63] : '=';
    out += left > 2 ? kAlphabet[triple & 63] : '=';
  }
  return out;
}

void write_report(const fs::path& dir, const Report& report) {
  write_file_atomically((dir / "claims.csv").string(), claims_csv(report));
  write_file_atomically((dir / "claims.json").string(), claims_json(report));
  write_file_atomically((dir / "report.md").string(), markdown(report));
  write_file_atomically((dir / "report.html").string(), html(dir, report));
}

std::vector<std::string> claim_summary_lines(const Report& report) {
  std::vector<std::string> lines;
  for (const StudySection& s : report.sections) {
    for (const Claim& c : s.outcome.claims) {
      lines.push_back(fmt::format("{:<29} {}: {} (expected {}, {})", verdict_text(judge(c)), c.id, measured_text(c),
                                  number(c.expected), tolerance_text(c)));
    }
  }
  lines.push_back(tally_text(report));
  return lines;
}

}  // namespace granule::reproduce
