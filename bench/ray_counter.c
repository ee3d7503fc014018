/* Counts the rays a program traces through Embree's single-ray and stream APIs (radiant traces
 * camera rays as streams, rtcIntersect1M; with --batching all, shadow rays too, rtcOccluded1M), for comparing rays per
 * second between radiant and Embree's own tutorial. Preload it:
 *   RAY_COUNTER_OUT=counts.txt LD_PRELOAD=build/bench/libray_counter.so pathtracer ...
 * At exit it writes "intersect N\noccluded M\n" to $RAY_COUNTER_OUT (or stderr). */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <embree3/rtcore.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>

static atomic_ullong intersect_count, occluded_count;

void rtcIntersect1(RTCScene scene, struct RTCIntersectContext* context, struct RTCRayHit* rayhit) {
  static void (*real)(RTCScene, struct RTCIntersectContext*, struct RTCRayHit*);
  if (!real) real = dlsym(RTLD_NEXT, "rtcIntersect1");
  atomic_fetch_add_explicit(&intersect_count, 1, memory_order_relaxed);
  real(scene, context, rayhit);
}

void rtcIntersect1M(RTCScene scene, struct RTCIntersectContext* context, struct RTCRayHit* rayhit, unsigned int M,
                    size_t byteStride) {
  static void (*real)(RTCScene, struct RTCIntersectContext*, struct RTCRayHit*, unsigned int, size_t);
  if (!real) real = dlsym(RTLD_NEXT, "rtcIntersect1M");
  atomic_fetch_add_explicit(&intersect_count, M, memory_order_relaxed);
  real(scene, context, rayhit, M, byteStride);
}

void rtcOccluded1(RTCScene scene, struct RTCIntersectContext* context, struct RTCRay* ray) {
  static void (*real)(RTCScene, struct RTCIntersectContext*, struct RTCRay*);
  if (!real) real = dlsym(RTLD_NEXT, "rtcOccluded1");
  atomic_fetch_add_explicit(&occluded_count, 1, memory_order_relaxed);
  real(scene, context, ray);
}

void rtcOccluded1M(RTCScene scene, struct RTCIntersectContext* context, struct RTCRay* ray, unsigned int M,
                   size_t byteStride) {
  static void (*real)(RTCScene, struct RTCIntersectContext*, struct RTCRay*, unsigned int, size_t);
  if (!real) real = dlsym(RTLD_NEXT, "rtcOccluded1M");
  atomic_fetch_add_explicit(&occluded_count, M, memory_order_relaxed);
  real(scene, context, ray, M, byteStride);
}

__attribute__((destructor)) static void report(void) {
  const char* path = getenv("RAY_COUNTER_OUT");
  FILE* out = path ? fopen(path, "w") : stderr;
  if (!out) return;
  fprintf(out, "intersect %llu\noccluded %llu\n", (unsigned long long)intersect_count,
          (unsigned long long)occluded_count);
  if (out != stderr) fclose(out);
}
