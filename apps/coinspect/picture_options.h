// Options shared by the picture commands (render, replay, plot-features, plot-timeline).
#pragma once

#include <string>

namespace coinspect::app {

struct PictureSize {
  int width = 0;
  int height = 0;
};

// "WxH" with both between 64 and 8192 pixels; throws InputError naming `source` otherwise.
PictureSize parsePictureSize(const std::string& text, const std::string& source);

}  // namespace coinspect::app
