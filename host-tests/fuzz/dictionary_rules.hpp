// Every value in a dictionary's RAM block fits its generated definition.
#pragma once

#include <string>

#include "costa/od/object_dictionary.hpp"

namespace costa::fuzz {

/// Empty when every RAM entry of `dictionary` holds a value its definition allows, else the
/// first entry that does not and why:
///  * BOOLEAN: 0 or 1;
///  * an entry with limits: LowLimit <= value <= HighLimit, read by its type (signed, unsigned
///    or real; NaN is outside every range);
///  * VISIBLE_STRING: the byte after its capacity (the terminating zero RAM keeps) is zero.
/// ROM entries (`const`) and DOMAINs hold nothing in RAM and are skipped.
std::string checkDictionaryValues(const od::ObjectDictionary& dictionary);

}  // namespace costa::fuzz
