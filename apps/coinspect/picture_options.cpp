#include "picture_options.h"

#include <cstdio>

#include "coinspect/core/error.h"

namespace coinspect::app {

PictureSize parsePictureSize(const std::string& text, const std::string& source) {
  PictureSize size;
  int consumed = 0;
  if (std::sscanf(text.c_str(), "%dx%d%n", &size.width, &size.height, &consumed) != 2 ||
      consumed != static_cast<int>(text.size()))
    throw InputError(source, "", "'" + text + "' is not WIDTHxHEIGHT (e.g. 1200x800)");
  for (const int pixels : {size.width, size.height})
    if (pixels < 64 || pixels > 8192)
      throw InputError(source, "", "'" + text + "': width and height must be 64 to 8192 pixels");
  return size;
}

}  // namespace coinspect::app
