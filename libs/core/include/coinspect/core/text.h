// Strict parsing of numbers and lists from text: the whole token must be a finite number.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace coinspect {

std::string_view trim(std::string_view text);

// Splits on any of the separator characters, trims each piece and drops empty pieces.
std::vector<std::string> splitTokens(std::string_view text, std::string_view separators = " \t,");

// nullopt unless the whole (trimmed) text is a finite number.
std::optional<double> parseFiniteDouble(std::string_view text);
std::optional<long long> parseInteger(std::string_view text);
// Accepts true/false, yes/no, on/off, 1/0 (case-insensitive).
std::optional<bool> parseBool(std::string_view text);

std::string toLower(std::string_view text);

// Text from a damaged or foreign file made safe to print and to store in JSON: valid UTF-8 and
// tab are kept, every other control character and every byte that is not part of a valid UTF-8
// sequence becomes \xNN (nlohmann::json refuses to write invalid UTF-8).
std::string printableText(std::string_view bytes);

}  // namespace coinspect
