#include "ply_layout.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <string_view>
#include <vector>

#include "coinspect/core/error.h"
#include "coinspect/core/text.h"
#include "file_utils.h"

namespace coinspect::world::detail {
namespace {

// Bytes of a PLY scalar type (both the 1.0 names and the sized ones), 0 when unknown.
size_t typeSize(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
      type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

struct Property {
  size_t size = 0;       // bytes of the scalar, or of each item of a list
  size_t countSize = 0;  // bytes of a list's count; 0 for a scalar
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
};

struct Header {
  std::string format;
  std::vector<Element> elements;
  size_t bodyStart = 0;
};

Header readHeader(const std::string& bytes, const std::string& source) {
  Header header;
  size_t at = 0;
  for (int line = 1;; ++line) {
    const size_t newline = bytes.find('\n', at);
    if (newline == std::string::npos)
      throw InputError(source, "", "the PLY header has no end_header line (a file cut short?)");
    const auto words = splitTokens(std::string_view(bytes).substr(at, newline - at), " \t\r");
    at = newline + 1;
    if (words.empty()) continue;
    if (words[0] == "end_header") break;
    if (words[0] == "format" && words.size() >= 2) {
      header.format = words[1];
    } else if (words[0] == "element") {
      const auto count = words.size() == 3 ? parseInteger(words[2]) : std::nullopt;
      if (!count || *count < 0)
        throw InputError(source, "line " + std::to_string(line),
                         "an element needs a name and a count");
      header.elements.push_back({words[1], static_cast<uint64_t>(*count), {}});
    } else if (words[0] == "property") {
      Property property;
      const bool list = words.size() >= 2 && words[1] == "list";
      if (list && words.size() == 5) {
        property.countSize = typeSize(words[2]);
        property.size = typeSize(words[3]);
      } else if (words.size() == 3) {
        property.size = typeSize(words[1]);
      }
      if (header.elements.empty() || property.size == 0 || (list && property.countSize == 0))
        throw InputError(source, "line " + std::to_string(line),
                         "not a property of a known type and element");
      header.elements.back().properties.push_back(property);
    }
    // "ply", comments, obj_info: nothing to check.
  }
  header.bodyStart = at;
  return header;
}

[[noreturn]] void cutShort(const std::string& source, const std::string& where,
                           const Element& element, uint64_t instance) {
  throw InputError(source, where,
                   "the PLY data ends in element '" + element.name + "' " +
                       std::to_string(instance) + " of " + std::to_string(element.count) +
                       " (a file cut short?)");
}

void checkAsciiBody(const std::string& bytes, const Header& header, const std::string& source) {
  size_t at = header.bodyStart;
  // The next whitespace-separated number, or an empty view at the end of the file.
  const auto next = [&]() {
    const size_t start = bytes.find_first_not_of(" \t\r\n", at);
    if (start == std::string::npos) return std::string_view();
    const size_t end = std::min(bytes.find_first_of(" \t\r\n", start), bytes.size());
    at = end;
    return std::string_view(bytes).substr(start, end - start);
  };
  for (const Element& element : header.elements) {
    if (element.properties.empty()) continue;  // takes no room, however many
    for (uint64_t i = 0; i < element.count; ++i)
      for (const Property& property : element.properties) {
        const auto first = next();
        if (first.empty()) cutShort(source, "", element, i);
        if (property.countSize == 0) continue;
        const auto items = parseInteger(first);
        if (!items || *items < 0)
          throw InputError(source, "element '" + element.name + "' " + std::to_string(i),
                           "list count '" + std::string(first) + "' is not a count");
        for (long long k = 0; k < *items; ++k)
          if (next().empty()) cutShort(source, "", element, i);
      }
  }
}

void checkBinaryBody(const std::string& bytes, const Header& header, const std::string& source) {
  const bool bigEndian = header.format == "binary_big_endian";
  size_t at = header.bodyStart;
  const auto need = [&](size_t size, const Element& element, uint64_t instance) {
    if (bytes.size() - at < size)
      cutShort(source, "byte offset " + std::to_string(at), element, instance);
  };
  for (const Element& element : header.elements) {
    if (element.properties.empty()) continue;
    for (uint64_t i = 0; i < element.count; ++i)
      for (const Property& property : element.properties) {
        if (property.countSize == 0) {
          need(property.size, element, i);
          at += property.size;
          continue;
        }
        need(property.countSize, element, i);
        uint64_t items = 0;  // unsigned, in the file's byte order
        for (size_t b = 0; b < property.countSize; ++b) {
          const size_t byte = bigEndian ? b : property.countSize - 1 - b;
          items = (items << 8) | static_cast<uint8_t>(bytes[at + byte]);
        }
        at += property.countSize;
        if (items > (bytes.size() - at) / property.size)
          cutShort(source, "byte offset " + std::to_string(at), element, i);
        at += items * property.size;
      }
  }
  // Bytes past the last declared element: a header whose counts were damaged (or a file joined
  // to another) would load as the part it declares, silently (fuzzing: 10 of 1068 faces).
  if (at != bytes.size())
    throw InputError(source, "byte offset " + std::to_string(at),
                     std::to_string(bytes.size() - at) +
                         " bytes after the last element the header declares (a damaged count?)");
}

}  // namespace

void checkPlyLayout(const std::filesystem::path& path, const std::string& source) {
  std::ifstream in(path, std::ios::binary);
  char magic[5] = {};
  in.read(magic, sizeof magic);
  if (std::string_view(magic, 4) != "ply\n" && std::string_view(magic, 5) != "ply\r\n") return;
  const std::string bytes = readWholeFile(path, "mesh file");
  const Header header = readHeader(bytes, source);
  if (header.format == "ascii")
    checkAsciiBody(bytes, header, source);
  else if (header.format == "binary_little_endian" || header.format == "binary_big_endian")
    checkBinaryBody(bytes, header, source);
  else
    throw InputError(source, "format", "unknown PLY format '" + header.format + "'");
}

}  // namespace coinspect::world::detail
