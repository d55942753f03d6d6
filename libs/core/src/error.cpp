#include "coinspect/core/error.h"

#include <cstdio>
#include <cstdlib>

namespace coinspect {

namespace {
std::string compose(const std::string& source, const std::string& where, const std::string& what) {
  std::string message = source;
  if (!where.empty()) message += ": " + where;
  return message + ": " + what;
}
}  // namespace

InputError::InputError(const std::string& source, const std::string& where, const std::string& what)
    : std::runtime_error(compose(source, where, what)), source_(source), where_(where) {}

void failAssertion(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "coinspect internal error: %s failed at %s:%d\n", condition, file, line);
  std::abort();
}

}  // namespace coinspect
