// The fields of the quirk profiles (costa/device_profile.hpp) with or without
// features::kQuirkProfiles:
//
//   COSTA_PROFILE_CHOICE bool errorResetFrame = true;  // its CiA 301 value
//
// declares a member with that default in a build with quirk profiles, and a constant of that
// value in a build without: reading it is the same code either way, assigning it does not
// compile, and every test of it folds to CiA 301's answer.
#pragma once

#include "costa/features.hpp"

#if COSTA_QUIRK_PROFILES
#define COSTA_PROFILE_CHOICE
#else
#define COSTA_PROFILE_CHOICE static constexpr
#endif
