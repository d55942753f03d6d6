// Errors: bad user input throws InputError naming where it came from; broken internal invariants
// are bugs and abort through COINSPECT_ASSERT.
#pragma once

#include <stdexcept>
#include <string>

namespace coinspect {

// Thrown for anything a user can get wrong: a file, a config key, a command-line value.
// The message always starts with the source (file path, or "--set") and the place in it
// (line, key, byte offset), so the user can go and fix it.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& source, const std::string& where, const std::string& what);

  const std::string& source() const { return source_; }
  const std::string& where() const { return where_; }

 private:
  std::string source_;
  std::string where_;
};

[[noreturn]] void failAssertion(const char* condition, const char* file, int line);

}  // namespace coinspect

#define COINSPECT_ASSERT(condition) \
  ((condition) ? static_cast<void>(0) : ::coinspect::failAssertion(#condition, __FILE__, __LINE__))
