#include "accel/embree_isa.h"

#include <embree3/rtcore.h>

namespace radiant {

namespace {

std::string config_for(const std::string& isa) { return "isa=" + isa + ",frequency_level=simd256"; }

// Whether a device of the packet widths `device` reports can be running `isa`. An ISA name this
// Embree does not know falls back to SSE2 without an error; the widths show it (when Embree was
// built with packets, which RAY_STREAM_SUPPORTED tells).
bool widths_agree(RTCDevice device, const std::string& isa) {
  if (!rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_RAY_STREAM_SUPPORTED)) return true;
  bool eight = rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED) != 0;
  bool sixteen = rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED) != 0;
  bool avx_family = isa == "avx" || isa == "avx2" || isa == "avx512";
  return eight == avx_family && sixteen == (isa == "avx512");
}

// Whether Embree creates a device for `isa` on this CPU, and it reports that ISA's packet widths.
bool embree_accepts(const std::string& isa) {
  RTCDevice device = rtcNewDevice(config_for(isa).c_str());
  if (!device) {
    rtcGetDeviceError(nullptr);  // clears this thread's error (RTC_ERROR_UNSUPPORTED_CPU)
    return false;
  }
  bool agrees = widths_agree(device, isa);
  rtcReleaseDevice(device);
  return agrees;
}

// "3.13.5", from a device of the configuration radiant uses.
std::string embree_version() {
  RTCDevice device = rtcNewDevice(embree_device_config().c_str());
  if (!device) return "unknown";
  long version = long(rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION));  // 31305: 3.13.5
  rtcReleaseDevice(device);
  return std::to_string(version / 10000) + "." + std::to_string(version / 100 % 100) + "." + std::to_string(version % 100);
}

}  // namespace

std::string best_accepted_isa(const std::function<bool(const std::string& isa)>& accepts) {
  for (const char* isa : {"avx512", "avx2", "avx", "sse4.2", "sse2"})
    if (accepts(isa)) return isa;
  return "";
}

const std::string& embree_isa_name() {
  // Asked once: a refused device costs microseconds, an accepted one starts and stops Embree's
  // tasking system.
  static const std::string isa = [] {
    std::string best = best_accepted_isa(embree_accepts);
    return best.empty() ? std::string("sse2") : best;  // no device at all: building the scene says so
  }();
  return isa;
}

std::string embree_kernels_name() {
  static const std::string name = embree_isa_name() + ", Embree " + embree_version();
  return name;
}

std::string embree_device_config() { return config_for(embree_isa_name()); }

}  // namespace radiant
