#include "coinspect/record/score_csv.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "coinspect/core/error.h"

namespace coinspect::record {

namespace {

constexpr const char* kHeader = "x, y, z, nx, ny, nz, score, idx";

// The reference streams floats with precision digits10 + 1 = 16 in the default (general)
// notation, which is printf's %.16g of the value promoted to double.
void put(std::string& line, double value, bool last) {
  char text[40];
  std::snprintf(text, sizeof text, last ? "%.16g" : "%.16g, ", value);
  line += text;
}

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

}  // namespace

void writeCaricScoreCsv(const std::filesystem::path& path, const world::InterestPointSet& points,
                        const std::vector<float>& gcsValues, ScoreCsvRows rows) {
  if (gcsValues.size() != points.size())
    throw InputError(path.string(), "score values",
                     std::to_string(gcsValues.size()) + " values for " +
                         std::to_string(points.size()) + " interest points");
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path.string(), "open", "cannot write the file");
  out << kHeader << '\n';
  std::string line;
  for (size_t i = 0; i < points.size(); ++i) {
    const float score = gcsValues[i];
    if (rows == ScoreCsvRows::Detected && !(score > 0.0f)) continue;
    const auto& p = points[i];
    line.clear();
    // Positions and normals pass through float, as in the reference's point cloud.
    for (int k = 0; k < 3; ++k)
      put(line, static_cast<float>(p.position[k]), false);
    for (int k = 0; k < 3; ++k)
      put(line, static_cast<float>(p.normal[k]), false);
    put(line, score, false);
    put(line, static_cast<float>(p.index), true);
    out << line << '\n';
  }
  if (!out) throw InputError(path.string(), "write", "writing the file failed");
}

std::vector<ScoreCsvRow> readCaricScoreCsv(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "open", "cannot read the file");
  const std::string source = path.string();
  std::string line;
  if (!std::getline(in, line))
    throw InputError(source, "line 1",
                     "empty file, expected the header \"" + std::string(kHeader) + "\"");
  std::string header;
  for (char c : line)
    if (c != ' ' && c != '\r') header += c;
  if (header != "x,y,z,nx,ny,nz,score,idx")
    throw InputError(source, "line 1", "expected the header \"" + std::string(kHeader) + "\"");
  std::vector<ScoreCsvRow> rows;
  for (size_t lineNumber = 2; std::getline(in, line); ++lineNumber) {
    const std::string where = "line " + std::to_string(lineNumber);
    if (trim(line).empty()) continue;
    std::istringstream fields(line);
    std::string field;
    double value[8];
    int count = 0;
    while (std::getline(fields, field, ',')) {
      if (count == 8) throw InputError(source, where, "more than 8 columns");
      const std::string text = trim(field);
      size_t used = 0;
      try {
        value[count] = std::stod(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (text.empty() || used != text.size() || !std::isfinite(value[count]))
        throw InputError(
            source, where,
            "column " + std::to_string(count + 1) + " is not a finite number: \"" + text + "\"");
      ++count;
    }
    if (count != 8)
      throw InputError(source, where, "expected 8 columns, found " + std::to_string(count));
    if (value[7] < 0 || value[7] != std::floor(value[7]) || value[7] > 4294967295.0)
      throw InputError(source, where, "idx is not a point index");
    ScoreCsvRow row;
    row.x = static_cast<float>(value[0]);
    row.y = static_cast<float>(value[1]);
    row.z = static_cast<float>(value[2]);
    row.nx = static_cast<float>(value[3]);
    row.ny = static_cast<float>(value[4]);
    row.nz = static_cast<float>(value[5]);
    row.score = static_cast<float>(value[6]);
    row.index = static_cast<uint32_t>(value[7]);
    rows.push_back(row);
  }
  return rows;
}

double totalScore(const std::vector<ScoreCsvRow>& rows) {
  double total = 0.0;
  for (const auto& row : rows)
    total += row.score;
  return total;
}

}  // namespace coinspect::record
