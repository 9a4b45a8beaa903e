#include "bench_report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace microsim::bench {

std::string toJson(const std::vector<BenchRow>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const BenchRow& r : rows) {
    nlohmann::json row = {{"bench", r.bench}, {"case", r.caseName}, {"metric", r.metric},
                          {"value", r.value}, {"unit", r.unit}};
    if (r.paper) row["paper"] = *r.paper;
    if (r.peer) row["peer"] = *r.peer;
    if (r.ratio) row["ratio"] = *r.ratio;
    out.push_back(std::move(row));
  }
  return out.dump(2);
}

namespace {

std::string formatNumber(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", v);
  return buffer;
}

std::string formatOptional(const std::optional<double>& v) {
  return v ? formatNumber(*v) : std::string("-");
}

}  // namespace

void printTable(std::ostream& out, const std::vector<BenchRow>& rows) {
  const std::vector<std::string> header = {"bench", "case", "metric", "ours", "unit",
                                           "paper", "peer", "ratio"};
  std::vector<std::vector<std::string>> cells;
  cells.push_back(header);
  for (const BenchRow& r : rows)
    cells.push_back({r.bench, r.caseName, r.metric, formatNumber(r.value), r.unit,
                     formatOptional(r.paper), formatOptional(r.peer), formatOptional(r.ratio)});

  // column widths from the widest cell
  std::vector<std::size_t> width(header.size(), 0);
  for (const auto& row : cells)
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());

  for (const auto& row : cells) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      const bool numeric = c >= 3 && c != 4;
      out << (numeric ? std::right : std::left) << std::setw(static_cast<int>(width[c])) << row[c];
      out << (c + 1 < row.size() ? "  " : "\n");
    }
  }
}

const BenchEntry* findBench(const std::string& name) {
  for (const BenchEntry& e : benchRegistry())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace microsim::bench
