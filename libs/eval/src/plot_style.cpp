#include <algorithm>
#include <array>

#include "coinspect/eval/run_plots.h"

namespace coinspect::eval {

Rgb unitColor(size_t i) {
  // Saturated and dark enough to read on light grey, kept away from the score ramp's red,
  // orange, yellow and green.
  static constexpr std::array<Rgb, 10> kPalette = {{{31, 119, 180},
                                                    {148, 70, 200},
                                                    {0, 170, 200},
                                                    {225, 80, 180},
                                                    {120, 75, 50},
                                                    {40, 40, 40},
                                                    {20, 45, 150},
                                                    {0, 125, 125},
                                                    {110, 110, 235},
                                                    {150, 30, 90}}};
  return kPalette[i % kPalette.size()];
}

int labelScale(int width, int height) {
  return std::clamp(std::min(width, height) / 300, 1, 4);
}

}  // namespace coinspect::eval
