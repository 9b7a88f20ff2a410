// A libFuzzer dictionary (-dict) for one device: byte strings of the fuzz encoding that start
// meaningful events, so that mutations reach the device's objects and services sooner.
#pragma once

#include <string>

#include "costa/od/definition.hpp"

namespace costa::fuzz {

/// The dictionary for a device with `definition`, in libFuzzer's format (one quoted token per
/// line, bytes as \xNN):
///  * for every entry: the start of an SDO upload to the node's own server (event 0xC0), and
///    of a segmented download and a block upload when it does not fit an expedited one;
///  * for every writable numeric entry of up to 4 bytes: whole expedited downloads of 0, its
///    default, its limits, and for 32-bit entries the default with bit 31 or bit 30 set;
///  * the NMT commands to all nodes, SYNC without and with a counter;
///  * the LSS requests (on 0x7E5) by command specifier;
///  * the store and restore signatures "save" and "load";
///  * for every word of the device's simulation commands (`controlWords`, space-separated):
///    the word, the command of the word alone (event 0x89), and the start of a 16-byte command
///    with the word.
std::string fuzzDictionary(const od::Definition& definition, const std::string& controlWords);

}  // namespace costa::fuzz
