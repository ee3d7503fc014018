#include "accel/accel_structure.h"

namespace radiant {

SceneAccel::~SceneAccel() {
  for (RTCScene s : mesh_scenes)
    if (s) rtcReleaseScene(s);
  if (top) rtcReleaseScene(top);
  if (device) rtcReleaseDevice(device);
}

}  // namespace radiant
