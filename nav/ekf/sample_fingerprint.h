#pragma once
#include <cstdint>

#include "nav/types/attitude_sample.h"
#include "nav/types/depth_sample.h"
#include "nav/types/dvl_sample.h"
#include "nav/types/heading_sample.h"
#include "nav/types/imu_sample.h"

namespace deepnav {

// 64-bit FNV-1a hash of the bits of a sample's measured values (not its stamp or stated sigma): two
// consecutive samples of a working sensor never share it, a frozen sensor repeats it.
std::uint64_t sampleFingerprint(const DvlSample& m);
std::uint64_t sampleFingerprint(const DepthSample& m);
std::uint64_t sampleFingerprint(const HeadingSample& m);
std::uint64_t sampleFingerprint(const AttitudeSample& m);
std::uint64_t sampleFingerprint(const ImuSample& m);

}  // namespace deepnav
