// The Embree ISA a shard records is the one its device was created with: the best one Embree
// accepts on this CPU, given to every device radiant creates.
#include <doctest/doctest.h>

#include <embree3/rtcore.h>

#include <string>
#include <vector>

#include "accel/embree_isa.h"

using namespace radiant;

TEST_CASE("embree isa: the best ISA accepted is taken, in the order avx512, avx2, avx, sse4.2, sse2") {
  std::vector<std::string> asked;
  auto accepts_up_to_avx = [&](const std::string& isa) {
    asked.push_back(isa);
    return isa == "avx" || isa == "sse4.2" || isa == "sse2";
  };
  CHECK(best_accepted_isa(accepts_up_to_avx) == "avx");
  CHECK(asked == std::vector<std::string>{"avx512", "avx2", "avx"});
  CHECK(best_accepted_isa([](const std::string&) { return true; }) == "avx512");
  CHECK(best_accepted_isa([](const std::string& isa) { return isa == "sse2"; }) == "sse2");
  CHECK(best_accepted_isa([](const std::string&) { return false; }).empty());
}

TEST_CASE("embree isa: radiant's device runs the ISA it names, and Embree accepts no better one here") {
  const std::string& isa = embree_isa_name();
  CAPTURE(isa);
  RTCDevice device = rtcNewDevice(embree_device_config().c_str());
  REQUIRE(device != nullptr);
  rtcReleaseDevice(device);
  const char* ladder[] = {"avx512", "avx2", "avx", "sse4.2", "sse2"};
  bool below = false;  // from radiant's ISA down, Embree creates devices; above it, it refuses
  for (const char* each : ladder) {
    CAPTURE(each);
    below = below || isa == each;
    RTCDevice tried = rtcNewDevice((std::string("isa=") + each).c_str());
    if (!below) {
      CHECK(tried == nullptr);
      CHECK(rtcGetDeviceError(nullptr) == RTC_ERROR_UNSUPPORTED_CPU);
    } else {
      REQUIRE(tried != nullptr);
      // The packet widths a device reports follow the ISA it was given: 8 from AVX, 16 with AVX-512.
      if (rtcGetDeviceProperty(tried, RTC_DEVICE_PROPERTY_RAY_STREAM_SUPPORTED)) {
        std::string name = each;
        CHECK((rtcGetDeviceProperty(tried, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED) != 0) ==
              (name == "avx" || name == "avx2" || name == "avx512"));
        CHECK((rtcGetDeviceProperty(tried, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED) != 0) == (name == "avx512"));
      }
    }
    if (tried) rtcReleaseDevice(tried);
  }
  CHECK(embree_kernels_name().rfind(isa + ", Embree 3.", 0) == 0);
}
