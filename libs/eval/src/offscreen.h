// Private to the 3D pictures: MRPT's offscreen renderer (CFBORender, EGL, headless) and its
// images as RgbImage.
#pragma once

#include <mrpt/opengl/CFBORender.h>

#include <memory>

#include "coinspect/eval/image.h"

namespace mrpt::img {
class CImage;
}

namespace coinspect::eval::detail {

// A renderer of width x height pixels on this thread's EGL context. The context is created by
// the first call on a thread and kept until the thread ends: destroying a context-owning
// CFBORender breaks the others (doc: MRPT field notes), so every renderer made here borrows it
// (create_EGL_context = false). Throws std::runtime_error naming the Debian packages that
// provide EGL when no context can be created.
std::unique_ptr<mrpt::opengl::CFBORender> makeOffscreenRenderer(int width, int height);

// The rendered picture as an RgbImage (CImage keeps OpenCV's blue-first channel order).
RgbImage toRgbImage(const mrpt::img::CImage& picture);

}  // namespace coinspect::eval::detail
