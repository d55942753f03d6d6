#include "coinspect/core/text.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace coinspect {

std::string_view trim(std::string_view text) {
  const auto isSpace = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!text.empty() && isSpace(text.front()))
    text.remove_prefix(1);
  while (!text.empty() && isSpace(text.back()))
    text.remove_suffix(1);
  return text;
}

std::vector<std::string> splitTokens(std::string_view text, std::string_view separators) {
  std::vector<std::string> tokens;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = text.find_first_of(separators, start);
    const auto piece =
        trim(text.substr(start, end == std::string_view::npos ? text.npos : end - start));
    if (!piece.empty()) tokens.emplace_back(piece);
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return tokens;
}

std::optional<double> parseFiniteDouble(std::string_view text) {
  text = trim(text);
  if (text.empty()) return std::nullopt;
  // strtod needs a terminated buffer; it also accepts hex floats and "inf"/"nan", which the
  // finiteness check below rejects.
  const std::string buffer(text);
  char* end = nullptr;
  const double value = std::strtod(buffer.c_str(), &end);
  if (end != buffer.c_str() + buffer.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<long long> parseInteger(std::string_view text) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  long long value = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size())
    return std::nullopt;
  return value;
}

std::string toLower(std::string_view text) {
  std::string lower(text);
  for (char& c : lower)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower;
}

std::optional<bool> parseBool(std::string_view text) {
  const std::string value = toLower(trim(text));
  if (value == "true" || value == "yes" || value == "on" || value == "1") return true;
  if (value == "false" || value == "no" || value == "off" || value == "0") return false;
  return std::nullopt;
}

}  // namespace coinspect
