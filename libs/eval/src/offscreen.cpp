#include "offscreen.h"

#include <mrpt/img/CImage.h>

#include <stdexcept>
#include <string>

namespace coinspect::eval::detail {

using mrpt::opengl::CFBORender;

namespace {

// MRPT's exceptions carry a call trace after the first line: people need the first line.
std::string firstLine(const std::string& text) {
  return text.substr(0, text.find('\n'));
}

// The thread's EGL context, created by the first renderer of the thread and kept until the
// thread ends: destroying a context-owning CFBORender breaks the others (field notes), so every
// renderer we create borrows this one (create_EGL_context = false).
void ensureThreadContext() {
  thread_local std::unique_ptr<CFBORender> owner;
  if (owner) return;
  try {
    owner = std::make_unique<CFBORender>(CFBORender::Parameters(8, 8));
  } catch (const std::exception& e) {
    throw std::runtime_error(
        "cannot create an offscreen EGL context for MRPT's CFBORender (it needs Mesa's EGL and "
        "software rasteriser, Debian packages libegl-mesa0 and libgl1-mesa-dri, which "
        "scripts/setup installs): " +
        firstLine(e.what()));
  }
}

}  // namespace

std::unique_ptr<CFBORender> makeOffscreenRenderer(int width, int height) {
  ensureThreadContext();
  CFBORender::Parameters parameters(static_cast<unsigned>(width), static_cast<unsigned>(height));
  parameters.create_EGL_context = false;
  return std::make_unique<CFBORender>(parameters);
}

RgbImage toRgbImage(const mrpt::img::CImage& picture) {
  const int width = static_cast<int>(picture.getWidth()),
            height = static_cast<int>(picture.getHeight());
  RgbImage image(width, height);
  // CImage keeps OpenCV's channel order (blue first) unless it says otherwise.
  const bool bgr = std::string(picture.getChannelsOrder()) != "RGB";
  for (int y = 0; y < height; ++y) {
    const uint8_t* row = picture.ptrLine<uint8_t>(static_cast<unsigned>(y));
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = row + 3 * x;
      image.at(x, y) = bgr ? Rgb{p[2], p[1], p[0]} : Rgb{p[0], p[1], p[2]};
    }
  }
  return image;
}

}  // namespace coinspect::eval::detail
