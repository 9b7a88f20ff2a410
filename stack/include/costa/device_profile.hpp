// Device-specific wire behaviour: one small profile per service, each given only to its service
// (and to the Linux tracer that decodes its frames). The core reads these fields and never
// tests for a device by name. Every field defaults to CiA 301, so `DeviceProfile{}` is a
// conformant slave; every profile is a literal type, so a device's profile is constexpr. A
// build without features::kQuirkProfiles (COSTA_FEATURE_QUIRK_PROFILES=OFF) makes every field a
// constant of its CiA 301 value (costa/profile_choice.hpp): a smaller image for a device that
// needs none of them.
#pragma once

#include "costa/emcy_profile.hpp"
#include "costa/error_control_profile.hpp"
#include "costa/pdo_profile.hpp"
#include "costa/sdo_profile.hpp"

namespace costa {

struct DeviceProfile {
  SdoProfile sdo{};
  PdoProfile pdo{};
  EmcyProfile emcy{};
  ErrorControlProfile errorControl{};
};

}  // namespace costa
