// SdoValueReader is defined in its header (inline: built for size, each of its functions is
// expanded into, or shares one copy with, the server's few callers). This unit compiles the
// header on its own, which checks that it includes what it uses.
#include "costa/sdo_value_reader.hpp"
