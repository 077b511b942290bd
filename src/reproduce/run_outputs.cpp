#include "reproduce/run_outputs.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace granule::reproduce {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

std::string PointOutputs::setting(const std::string& key) const {
  for (const auto& [k, v] : settings) {
    if (k == key) return v;
  }
  return "";
}

std::vector<const PointOutputs*> points_with(const GroupOutputs& group, const std::string& key, const std::string& value) {
  std::vector<const PointOutputs*> chosen;
  for (const PointOutputs& p : group) {
    if (p.usable() && (key.empty() || p.setting(key) == value)) chosen.push_back(&p);
  }
  return chosen;
}

Estimate mean_over(const std::vector<double>& values) {
  Estimate e;
  double sum = 0.0;
  for (double v : values) {
    if (std::isfinite(v)) {
      sum += v;
      ++e.count;
    }
  }
  if (e.count == 0) return {kNaN, kNaN, 0};
  e.mean = sum / e.count;
  if (e.count < kLeastValuesForAnError) {
    e.error = kNaN;
    return e;
  }
  double squares = 0.0;
  for (double v : values) {
    if (std::isfinite(v)) squares += (v - e.mean) * (v - e.mean);
  }
  e.error = std::sqrt(squares / (e.count - 1) / e.count);
  return e;
}

std::vector<std::map<std::string, std::string>> read_csv_rows(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::map<std::string, std::string>> rows;
  std::string line;
  if (!std::getline(in, line)) return rows;
  std::vector<std::string> header;
  std::istringstream names(line);
  for (std::string name; std::getline(names, name, ',');) header.push_back(name);
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    std::map<std::string, std::string> row;
    std::size_t k = 0;
    for (std::string cell; std::getline(cells, cell, ',') && k < header.size(); ++k) row[header[k]] = cell;
    rows.push_back(std::move(row));
  }
  return rows;
}

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  if (n < 3 || y.size() != n) return {kNaN, kNaN, kNaN};
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  if (sxx <= 0.0) return {kNaN, kNaN, kNaN};
  LineFit fit;
  fit.slope = sxy / sxx;
  fit.intercept = my - fit.slope * mx;
  double residuals = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = y[i] - fit.intercept - fit.slope * x[i];
    residuals += r * r;
  }
  fit.slope_error = std::sqrt(residuals / static_cast<double>(n - 2) / sxx);
  return fit;
}

EarlyDecay early_decay(const std::vector<DiagnosticsSample>& samples, double early_to_c, double excess) {
  EarlyDecay decay;
  std::vector<double> c, log_temperature, log_energy;
  for (const DiagnosticsSample& s : samples) {
    if (s.c >= 1.0 && s.c <= early_to_c) {
      c.push_back(s.c);
      log_temperature.push_back(std::log(s.temperature));
      log_energy.push_back(std::log(s.kinetic_energy));
    }
  }
  decay.temperature_slope = fit_line(c, log_temperature).slope;
  const LineFit energy = fit_line(c, log_energy);
  for (const DiagnosticsSample& s : samples) {
    if (s.c > 1.0 && std::log(s.kinetic_energy) - (energy.intercept + energy.slope * s.c) > std::log(excess)) {
      decay.onset_c = s.c;
      break;
    }
  }
  return decay;
}

}  // namespace granule::reproduce
