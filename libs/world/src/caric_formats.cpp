#include "coinspect/world/caric_formats.h"

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <set>
#include <sstream>

#include "coinspect/core/error.h"
#include "coinspect/core/text.h"
#include "file_utils.h"

namespace coinspect::world {
namespace {

using detail::putF32;
using detail::putU32;
using detail::readWholeFile;

std::string lineName(int line) {
  return "line " + std::to_string(line);
}

// ---------------------------------------------------------------------------------------------
// PCD

struct PcdField {
  std::string name;
  int size = 0;
  char type = '?';
  int count = 0;
  size_t offset = 0;
};

uint32_t getU32(const std::string& bytes, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i)
    v |= static_cast<uint32_t>(static_cast<uint8_t>(bytes[at + i])) << (8 * i);
  return v;
}

float getF32(const std::string& bytes, size_t at) {
  const uint32_t bits = getU32(bytes, at);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace

std::vector<InterestPoint> readCaricInterestPoints(const std::filesystem::path& path) {
  const std::string source = path.string();
  const std::string bytes = readWholeFile(path, "interest point file");

  // Header: text lines up to and including "DATA ...".
  std::vector<std::string> names, sizes, types, counts;
  int namesLine = 0, sizesLine = 0, typesLine = 0, countsLine = 0;
  long long width = -1, height = -1, points = -1;
  size_t at = 0;
  int line = 0;
  bool dataSeen = false;
  while (!dataSeen) {
    if (at >= bytes.size())
      throw InputError(source, lineName(line), "header ends without a DATA line");
    const size_t end = bytes.find('\n', at);
    const std::string text =
        bytes.substr(at, end == std::string::npos ? std::string::npos : end - at);
    at = end == std::string::npos ? bytes.size() : end + 1;
    ++line;
    const auto content = trim(text);
    if (content.empty() || content.front() == '#') continue;
    auto tokens = splitTokens(content, " \t\r");
    const std::string key = tokens.front();
    tokens.erase(tokens.begin());
    const auto single = [&](const char* what) {
      if (tokens.size() != 1)
        throw InputError(source, lineName(line), std::string(what) + " needs one value");
      const auto value = parseInteger(tokens[0]);
      if (!value || *value < 0)
        throw InputError(source, lineName(line),
                         std::string(what) + " '" + tokens[0] + "' is not a non-negative integer");
      return *value;
    };
    if (key == "VERSION" || key == "VIEWPOINT") continue;
    if (key == "FIELDS")
      names = tokens, namesLine = line;
    else if (key == "SIZE")
      sizes = tokens, sizesLine = line;
    else if (key == "TYPE")
      types = tokens, typesLine = line;
    else if (key == "COUNT")
      counts = tokens, countsLine = line;
    else if (key == "WIDTH")
      width = single("WIDTH");
    else if (key == "HEIGHT")
      height = single("HEIGHT");
    else if (key == "POINTS")
      points = single("POINTS");
    else if (key == "DATA") {
      if (tokens.size() != 1 || tokens[0] != "binary")
        throw InputError(source, lineName(line),
                         "only 'DATA binary' is supported, got '" + std::string(content) + "'");
      dataSeen = true;
    } else {
      throw InputError(source, lineName(line), "unknown PCD header key '" + key + "'");
    }
  }
  const size_t dataStart = at;

  if (names.empty()) throw InputError(source, "header", "no FIELDS line");
  if (sizes.size() != names.size())
    throw InputError(source, lineName(sizesLine ? sizesLine : namesLine),
                     "SIZE has " + std::to_string(sizes.size()) + " entries for " +
                         std::to_string(names.size()) + " FIELDS");
  if (types.size() != names.size())
    throw InputError(source, lineName(typesLine ? typesLine : namesLine),
                     "TYPE has " + std::to_string(types.size()) + " entries for " +
                         std::to_string(names.size()) + " FIELDS");
  // COUNT is optional in PCD (default 1 per field).
  if (!counts.empty() && counts.size() != names.size())
    throw InputError(source, lineName(countsLine),
                     "COUNT has " + std::to_string(counts.size()) + " entries for " +
                         std::to_string(names.size()) + " FIELDS");
  std::vector<PcdField> fields(names.size());
  size_t recordSize = 0;
  for (size_t i = 0; i < names.size(); ++i) {
    PcdField& f = fields[i];
    f.name = names[i];
    const auto size = parseInteger(sizes[i]);
    const auto count = counts.empty() ? std::optional<long long>(1) : parseInteger(counts[i]);
    if (!size || (*size != 1 && *size != 2 && *size != 4 && *size != 8))
      throw InputError(source, lineName(sizesLine),
                       "bad SIZE '" + sizes[i] + "' of field " + f.name);
    if (!count || *count < 1)
      throw InputError(source, lineName(countsLine), "bad COUNT of field " + f.name);
    if (types[i].size() != 1 || std::string("FUI").find(types[i][0]) == std::string::npos)
      throw InputError(source, lineName(typesLine),
                       "bad TYPE '" + types[i] + "' of field " + f.name);
    f.size = static_cast<int>(*size);
    f.count = static_cast<int>(*count);
    f.type = types[i][0];
    f.offset = recordSize;
    recordSize += static_cast<size_t>(f.size * f.count);
  }
  // The six float fields we need; any other field (CARIC's 4-byte "_") is padding.
  const char* required[6] = {"x", "y", "z", "normal_x", "normal_y", "normal_z"};
  size_t offsets[6];
  for (int k = 0; k < 6; ++k) {
    size_t found = fields.size();
    for (size_t i = 0; i < fields.size(); ++i)
      if (fields[i].name == required[k]) found = i;
    if (found == fields.size())
      throw InputError(source, lineName(namesLine),
                       std::string("FIELDS lacks '") + required[k] +
                           "' (need x y z normal_x normal_y normal_z)");
    const PcdField& f = fields[found];
    if (f.type != 'F' || f.size != 4 || f.count != 1)
      throw InputError(source, lineName(namesLine),
                       "field '" + f.name + "' must be one 4-byte float (TYPE F, SIZE 4, COUNT 1)");
    offsets[k] = f.offset;
  }
  if (points < 0) throw InputError(source, "header", "no POINTS line");
  if (width >= 0 && height >= 0 && width * height != points)
    throw InputError(source, "header",
                     "WIDTH x HEIGHT = " + std::to_string(width * height) +
                         " but POINTS = " + std::to_string(points));

  const size_t expected = static_cast<size_t>(points) * recordSize;
  const size_t available = bytes.size() - dataStart;
  if (available < expected)
    throw InputError(source, "byte " + std::to_string(bytes.size()),
                     "point data ends after " + std::to_string(available) + " bytes, expected " +
                         std::to_string(expected) + " (" + std::to_string(points) + " points x " +
                         std::to_string(recordSize) + " bytes from byte " +
                         std::to_string(dataStart) + ")");
  // The reference files carry zero padding after the last record; anything else means the
  // header does not describe the data.
  for (size_t i = dataStart + expected; i < bytes.size(); ++i)
    if (bytes[i] != '\0')
      throw InputError(source, "byte " + std::to_string(i),
                       "non-zero byte after the last of " + std::to_string(points) +
                           " records (data ends at byte " + std::to_string(dataStart + expected) +
                           ")");

  std::vector<InterestPoint> result(static_cast<size_t>(points));
  for (size_t i = 0; i < result.size(); ++i) {
    const size_t record = dataStart + i * recordSize;
    double v[6];
    for (int k = 0; k < 6; ++k)
      v[k] = getF32(bytes, record + offsets[k]);
    result[i].position = Vec3(v[0], v[1], v[2]);
    result[i].normal = Vec3(v[3], v[4], v[5]);
    result[i].index = static_cast<uint32_t>(i);
  }
  validateInterestPoints(result, source);
  return result;
}

void writeCaricInterestPoints(const std::vector<InterestPoint>& points,
                              const std::filesystem::path& path) {
  const std::string n = std::to_string(points.size());
  std::string bytes =
      "# .PCD v0.7 - Point Cloud Data file format\n"
      "VERSION 0.7\n"
      "FIELDS normal_x normal_y normal_z x y z _\n"
      "SIZE 4 4 4 4 4 4 1\n"
      "TYPE F F F F F F U\n"
      "COUNT 1 1 1 1 1 1 4\n"
      "WIDTH " +
      n +
      "\n"
      "HEIGHT 1\n"
      "VIEWPOINT 0 0 0 1 0 0 0\n"
      "POINTS " +
      n +
      "\n"
      "DATA binary\n";
  bytes.reserve(bytes.size() + 28 * points.size());
  for (const auto& p : points) {
    for (int k = 0; k < 3; ++k)
      putF32(bytes, static_cast<float>(p.normal[k]));
    for (int k = 0; k < 3; ++k)
      putF32(bytes, static_cast<float>(p.position[k]));
    putU32(bytes, 0);
  }
  detail::writeWholeFile(path, bytes);
}

// ---------------------------------------------------------------------------------------------
// box_description.yaml

namespace {

struct YamlList {
  int line = 0;                                     // where the key is
  std::vector<std::pair<int, std::string>> pieces;  // text between the brackets, per line
  bool present = false;
};

struct YamlBox {
  std::string name;
  int line = 0;
  YamlList center, size, orientation;
};

std::vector<double> parseYamlList(const YamlList& list, size_t expected, const std::string& source,
                                  const std::string& what) {
  std::vector<double> values;
  for (const auto& [line, text] : list.pieces)
    for (const auto& token : splitTokens(text, ",")) {
      const auto value = parseFiniteDouble(token);
      if (!value)
        throw InputError(source, lineName(line), what + ": '" + token + "' is not a finite number");
      values.push_back(*value);
    }
  if (values.size() != expected)
    throw InputError(source, lineName(list.line),
                     what + " needs " + std::to_string(expected) + " numbers, got " +
                         std::to_string(values.size()));
  return values;
}

}  // namespace

std::vector<OrientedBox> readCaricBoxes(const std::filesystem::path& path) {
  const std::string source = path.string();
  std::istringstream lines(readWholeFile(path, "box description"));

  std::vector<YamlBox> parsed;
  YamlList* open = nullptr;     // list whose closing bracket is awaited
  YamlList* pending = nullptr;  // key seen, its opening bracket is awaited
  std::string raw;
  int line = 0;
  // Appends the text after '[' (or a continuation line) to the open list; closes it at ']'.
  const auto collect = [&](std::string_view text) {
    const size_t close = text.find(']');
    open->pieces.emplace_back(line, std::string(text.substr(0, close)));
    if (close == std::string_view::npos) return;
    if (!trim(text.substr(close + 1)).empty())
      throw InputError(source, lineName(line), "unexpected text after ']'");
    if (open->pieces.back().second.find('[') != std::string::npos)
      throw InputError(source, lineName(line), "nested lists are not expected");
    open = nullptr;
  };
  while (std::getline(lines, raw)) {
    ++line;
    std::string_view text = raw;
    // YAML comments; no value of this file contains '#'.
    text = text.substr(0, text.find('#'));
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
      text.remove_suffix(1);
    if (trim(text).empty()) continue;
    if (open) {
      collect(text);
      continue;
    }
    const auto content = trim(text);
    if (pending) {
      if (content.front() != '[')
        throw InputError(source, lineName(line), "expected a '[ ... ]' list");
      open = pending;
      pending = nullptr;
      collect(content.substr(1));
      continue;
    }
    const size_t colon = content.find(':');
    if (colon == std::string_view::npos)
      throw InputError(source, lineName(line),
                       "expected 'key:', got '" + std::string(content) + "'");
    const std::string key(trim(content.substr(0, colon)));
    const auto rest = trim(content.substr(colon + 1));
    const bool topLevel = !std::isspace(static_cast<unsigned char>(text.front()));
    if (topLevel) {
      if (!rest.empty())
        throw InputError(source, lineName(line), "a box name line must be just '" + key + ":'");
      for (const auto& box : parsed)
        if (box.name == key)
          throw InputError(
              source, lineName(line),
              "duplicate box '" + key + "' (first at line " + std::to_string(box.line) + ")");
      parsed.push_back(YamlBox{key, line, {}, {}, {}});
      continue;
    }
    if (parsed.empty())
      throw InputError(source, lineName(line), "indented key '" + key + "' outside a box");
    YamlBox& box = parsed.back();
    YamlList* list = key == "center"        ? &box.center
                     : key == "size"        ? &box.size
                     : key == "orientation" ? &box.orientation
                                            : nullptr;
    if (!list)
      throw InputError(source, lineName(line),
                       "unknown key '" + key + "' (expected center, size, orientation)");
    if (list->present)
      throw InputError(source, lineName(line), "duplicate key '" + key + "' in " + box.name);
    list->present = true;
    list->line = line;
    if (rest.empty()) {
      pending = list;
    } else if (rest.front() == '[') {
      open = list;
      collect(rest.substr(1));
    } else {
      throw InputError(source, lineName(line), "expected a '[ ... ]' list after '" + key + ":'");
    }
  }
  if (open) throw InputError(source, lineName(open->line), "list is never closed with ']'");
  if (pending) throw InputError(source, lineName(pending->line), "key has no value");
  if (parsed.empty()) throw InputError(source, "", "no boxes");

  std::vector<OrientedBox> boxes;
  for (const YamlBox& y : parsed) {
    for (const auto& [list, key] : {std::pair<const YamlList*, const char*>{&y.center, "center"},
                                    {&y.size, "size"},
                                    {&y.orientation, "orientation"}})
      if (!list->present)
        throw InputError(source, lineName(y.line), "box '" + y.name + "' has no '" + key + "'");
    OrientedBox box;
    box.name = y.name;
    const auto center = parseYamlList(y.center, 3, source, y.name + " center");
    const auto size = parseYamlList(y.size, 3, source, y.name + " size");
    const auto m = parseYamlList(y.orientation, 16, source, y.name + " orientation");
    box.center = Vec3(center[0], center[1], center[2]);
    box.size = Vec3(size[0], size[1], size[2]);
    if ((box.size.array() <= 0.0).any())
      throw InputError(source, lineName(y.size.line),
                       "box '" + y.name + "' size must be positive along every axis");
    // Row-major 4x4; its 3x3 block maps box coordinates to the world (checked on the MBS data,
    // see caric_formats.h). The translation column is not always equal to `center` (MBS box3
    // differs by 15 cm in z) and the reference uses `center`, so it is ignored.
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        box.rotation(r, c) = m[4 * r + c];
    // The file's matrices carry 12 digits but are orthonormal only to about 1e-5 (MBS box4:
    // 6e-6). Accept up to 1e-3 and project onto the nearest rotation, so that every later
    // computation (validateBox, toBox as the transpose) sees an exact rotation.
    const Eigen::Matrix3d block = box.rotation;
    const double orthoError =
        (block.transpose() * block - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (!(orthoError <= 1e-3) || block.determinant() <= 0.0)
      throw InputError(
          source, lineName(y.orientation.line),
          "box '" + y.name + "' orientation is not a rotation (R^T R deviates from I by " +
              std::to_string(orthoError) + ", det " + std::to_string(block.determinant()) + ")");
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(block, Eigen::ComputeFullU | Eigen::ComputeFullV);
    box.rotation = svd.matrixU() * svd.matrixV().transpose();
    validateBox(box, source);
    boxes.push_back(box);
  }
  return boxes;
}

// ---------------------------------------------------------------------------------------------
// caric_ppcom_network_*.txt

std::vector<CaricNetworkUnit> readCaricNetwork(const std::filesystem::path& path) {
  static const char* kFieldNames[16] = {
      "Name",         "Role",      "AntOffset",         "HorzFOV",        "VertFOV",
      "CamPosX",      "CamPosY",   "CamPosZ",           "ExposureTime",   "TriggerInterval",
      "FocalLength",  "PixelSize", "DesiredMmPerPixel", "GimbalPitchMax", "GimbalYawMax",
      "GimbalRateMax"};
  const std::string source = path.string();
  std::istringstream lines(readWholeFile(path, "network file"));
  std::vector<CaricNetworkUnit> units;
  std::set<std::string> names;
  std::string raw;
  for (int line = 1; std::getline(lines, raw); ++line) {
    const auto content = trim(std::string_view(raw).substr(0, raw.find('#')));
    if (content.empty()) continue;
    // Split on every comma, keeping empty fields so that ",," counts as a (bad) field.
    std::vector<std::string> fields;
    size_t start = 0;
    while (true) {
      const size_t comma = content.find(',', start);
      fields.emplace_back(trim(content.substr(
          start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    if (fields.size() != 16)
      throw InputError(source, lineName(line),
                       "expected 16 comma-separated fields, got " + std::to_string(fields.size()));
    double v[16] = {};
    for (int i = 2; i < 16; ++i) {
      const auto value = parseFiniteDouble(fields[i]);
      if (!value)
        throw InputError(source, lineName(line),
                         "field " + std::to_string(i + 1) + " (" + kFieldNames[i] + ") '" +
                             fields[i] + "' is not a finite number");
      v[i] = *value;
    }
    CaricNetworkUnit unit;
    unit.name = fields[0];
    unit.role = toLower(fields[1]);
    if (unit.name.empty()) throw InputError(source, lineName(line), "empty unit name");
    if (unit.role != "manager" && unit.role != "peer")
      throw InputError(source, lineName(line),
                       "role '" + fields[1] + "' is neither 'manager' nor 'peer'");
    if (!names.insert(unit.name).second)
      throw InputError(source, lineName(line), "duplicate unit '" + unit.name + "'");
    // Same expression as CameraSpec's defaults, so that CARIC values compare equal to them.
    const auto rad = [](double degrees) { return degrees * M_PI / 180.0; };
    unit.antennaOffset = v[2];
    CameraSpec& c = unit.camera;
    c.horizontalFov = rad(v[3]);
    c.verticalFov = rad(v[4]);
    c.positionInBody = Vec3(v[5], v[6], v[7]);
    c.exposureTime = v[8];
    c.triggerInterval = v[9];
    c.focalLength = v[10];
    c.pixelSize = v[11];
    c.desiredMmPerPixel = v[12];
    c.gimbalPitchMax = rad(v[13]);
    c.gimbalYawMax = rad(v[14]);
    c.gimbalRateMax = rad(v[15]);
    // Checked here too (the scenario checks the fleet again), to name the line.
    const std::string where = lineName(line) + " (unit '" + unit.name + "')";
    if (unit.antennaOffset < 0.0)
      throw InputError(source, where, "field 3 (AntOffset) must not be negative");
    validateCamera(c, source, where);
    units.push_back(unit);
  }
  if (units.empty()) throw InputError(source, "", "no units");
  return units;
}

// ---------------------------------------------------------------------------------------------
// run_*.launch

namespace {

// Value of attribute `name` in the tag text, if present.
std::optional<std::string> attribute(std::string_view tag, std::string_view name) {
  size_t at = 0;
  while ((at = tag.find(name, at)) != std::string_view::npos) {
    const bool boundary = at == 0 || std::isspace(static_cast<unsigned char>(tag[at - 1]));
    size_t p = at + name.size();
    while (p < tag.size() && std::isspace(static_cast<unsigned char>(tag[p])))
      ++p;
    if (boundary && p < tag.size() && tag[p] == '=') {
      ++p;
      while (p < tag.size() && std::isspace(static_cast<unsigned char>(tag[p])))
        ++p;
      if (p < tag.size() && (tag[p] == '"' || tag[p] == '\'')) {
        const size_t close = tag.find(tag[p], p + 1);
        if (close != std::string_view::npos) return std::string(tag.substr(p + 1, close - p - 1));
      }
    }
    at += name.size();
  }
  return std::nullopt;
}

}  // namespace

std::map<std::string, CaricStartPose> readCaricStartPoses(const std::filesystem::path& path) {
  const std::string source = path.string();
  std::string text = readWholeFile(path, "launch file");
  // Blank out XML comments (keeping newlines for line numbers): commented-out args must not count.
  for (size_t open = text.find("<!--"); open != std::string::npos; open = text.find("<!--", open)) {
    const size_t close = text.find("-->", open + 4);
    const size_t end = close == std::string::npos ? text.size() : close + 3;
    for (size_t i = open; i < end; ++i)
      if (text[i] != '\n') text[i] = ' ';
  }
  const auto lineAt = [&](size_t offset) {
    return 1 + static_cast<int>(
                   std::count(text.begin(), text.begin() + static_cast<long>(offset), '\n'));
  };

  std::map<std::string, CaricStartPose> poses;
  for (size_t at = text.find("<include"); at != std::string::npos; at = text.find("<include", at)) {
    const size_t tagEnd = text.find('>', at);
    if (tagEnd == std::string::npos) throw InputError(source, lineName(lineAt(at)), "unclosed tag");
    size_t blockEnd = tagEnd;
    if (text[tagEnd - 1] != '/') {
      blockEnd = text.find("</include>", tagEnd);
      if (blockEnd == std::string::npos)
        throw InputError(source, lineName(lineAt(at)), "<include> without </include>");
    }
    const int blockLine = lineAt(at);
    std::map<std::string, std::pair<std::string, int>> args;  // name -> (value, line)
    for (size_t a = text.find("<arg", tagEnd); a != std::string::npos && a < blockEnd;
         a = text.find("<arg", a + 4)) {
      const size_t end = text.find('>', a);
      if (end == std::string::npos) throw InputError(source, lineName(lineAt(a)), "unclosed <arg");
      const std::string_view tag(text.data() + a, end - a);
      const auto name = attribute(tag, "name");
      const auto value = attribute(tag, "value");
      if (name && value) args[*name] = {*value, lineAt(a)};
    }
    at = blockEnd;

    std::string unit;
    for (const char* key : {"namespace", "ppcom_id"})
      if (unit.empty() && args.count(key)) unit = trim(args[key].first);
    if (unit.empty()) continue;  // not a spawn (e.g. the Gazebo world include)
    if (poses.count(unit))
      throw InputError(source, lineName(blockLine), "unit '" + unit + "' is spawned twice");

    const auto number = [&](std::initializer_list<const char*> keys,
                            std::optional<double> fallback) -> double {
      for (const char* key : keys) {
        const auto it = args.find(key);
        if (it == args.end()) continue;
        const auto value = parseFiniteDouble(it->second.first);
        if (!value)
          throw InputError(source, lineName(it->second.second),
                           "spawn of '" + unit + "': " + key + " '" + it->second.first +
                               "' is not a finite number");
        return *value;
      }
      if (!fallback)
        throw InputError(source, lineName(blockLine),
                         "spawn of '" + unit + "' has no " + *keys.begin() + " coordinate");
      return *fallback;
    };
    CaricStartPose pose;
    // spawn_uav.launch places UAVs at z = 0.1 unless told otherwise.
    pose.position = Vec3(number({"x", "start_x"}, std::nullopt),
                         number({"y", "start_y"}, std::nullopt), number({"z", "start_z"}, 0.1));
    pose.yaw = number({"yaw", "start_yaw", "Y"}, 0.0);
    if (args.count("role")) pose.role = toLower(trim(args["role"].first));
    poses[unit] = pose;
  }
  if (poses.empty()) throw InputError(source, "", "no unit spawns (<include> with a namespace)");
  return poses;
}

}  // namespace coinspect::world
