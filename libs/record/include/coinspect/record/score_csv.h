// The CARIC score file: the ground station's value per interest point at the end of a run, in
// the format the reference's mission manager writes (caric_mission, MissionManager.cpp,
// WriteScoreLog; see doc/recording.md, "Side outputs").
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "coinspect/world/interest_points.h"

namespace coinspect::record {

// Which rows a score file holds. The reference writes only the points the ground station has
// a score > 0 for; `All` adds a row (score 0) for every other point, same format.
enum class ScoreCsvRows { Detected, All };

// One row: the columns x, y, z, nx, ny, nz, score, idx.
struct ScoreCsvRow {
  float x = 0, y = 0, z = 0;
  float nx = 0, ny = 0, nz = 0;
  float score = 0;
  uint32_t index = 0;
};

// Writes the header "x, y, z, nx, ny, nz, score, idx" and one row per point in index order,
// values in single precision printed with 16 significant digits and ", " between columns, as
// the reference does. `gcsValues[i]` is the ground station's value of point i (the tally).
// Throws InputError when the sizes differ or the file cannot be written.
void writeCaricScoreCsv(const std::filesystem::path& path, const world::InterestPointSet& points,
                        const std::vector<float>& gcsValues,
                        ScoreCsvRows rows = ScoreCsvRows::Detected);

// Reads a score file written by the reference or by writeCaricScoreCsv (header required,
// spaces around commas optional). Throws InputError naming the file and line.
std::vector<ScoreCsvRow> readCaricScoreCsv(const std::filesystem::path& path);

// Sum of the score column, in double in file order (the reference's total).
double totalScore(const std::vector<ScoreCsvRow>& rows);

}  // namespace coinspect::record
