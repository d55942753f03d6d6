#include "coinspect/planning/camera_limits.h"

namespace coinspect::planning {

double fullResolutionDistance(const CameraOptics& optics) {
  return optics.desiredMmPerPixel * optics.focalLength / (1000.0 * optics.pixelSize);
}

double blurFreeSpeed(const CameraOptics& optics, double distance) {
  return optics.pixelSize * distance / (optics.focalLength * optics.exposure);
}

}  // namespace coinspect::planning
