// SDO and LSS parts of FrameTracer.
#include <algorithm>
#include <cstdio>

#include "costa/od/abort_code.hpp"
#include "costa/od/little_endian.hpp"
#include "frame_trace.hpp"

namespace costa::host {
namespace {

std::string hex32(uint32_t value) {
  char buffer[16];
  std::snprintf(buffer, sizeof(buffer), "0x%08X", value);
  return buffer;
}

std::string hex16(uint16_t value) {
  char buffer[8];
  std::snprintf(buffer, sizeof(buffer), "0x%04X", value);
  return buffer;
}

// The n field (bits 4..2) of a block end frame.
std::string unusedText(uint8_t command) {
  const unsigned unused = (command >> 2U) & 7U;
  return std::to_string(unused) + (unused == 1U ? " byte unused" : " bytes unused");
}

std::string abortText(const uint8_t* data, const std::string& entry) {
  const uint32_t code = loadU32(data + 4);
  return "SDO abort " + entry + " " + hex32(code) + " (" + describe(static_cast<AbortCode>(code)) +
         ")";
}

}  // namespace

std::string FrameTracer::describeSdoRequest(const CanFrame& frame, bool local) {
  // The local node may serve requests shorter than 8 bytes (SdoProfile::shortestRequest).
  const uint8_t shortest = local && profile_.sdo.shortestRequest != 0U
                               ? profile_.sdo.shortestRequest
                               : static_cast<uint8_t>(local ? 1U : 8U);
  if (frame.rtr || frame.dlc > 8U || frame.dlc < shortest) {
    return "SDO request (malformed, ignored)";
  }
  if (frame.dlc < 8U) {
    uint8_t whole[8] = {};
    std::copy(frame.data, frame.data + frame.dlc, whole);
    return describeSdoRequestData(whole, local) + " (" + std::to_string(frame.dlc) +
           " bytes, the rest taken as 0)";
  }
  return describeSdoRequestData(frame.data, local);
}

std::string FrameTracer::describeSdoRequestData(const uint8_t* d, bool local) {
  if (block_ == Block::kDownloadSegments && d[0] != 0x80U) {
    return describeBlockSegment(d);
  }
  const uint16_t index = loadU16(d + 1);
  const uint8_t sub = d[3];
  const std::string entry = entryText(index, sub);
  switch (d[0] >> 5U) {
    case 0: {
      const size_t count = 7U - ((d[0] >> 1U) & 7U);
      const bool last = (d[0] & 1U) != 0U;
      collected_.insert(collected_.end(), d + 1, d + 1 + count);
      std::string text = "SDO download segment " + formatValue(0, 0, d + 1, count, false);
      if (last && downloading_) {
        text += " (last) " + entryText(index_, subIndex_) + " = " +
                formatValue(index_, subIndex_, collected_.data(), collected_.size(), local);
        downloading_ = false;
      }
      return text;
    }
    case 1: {
      // e = s = 0 with a byte count: expedited for a node that reads the count alone.
      const bool countAlone = local && profile_.sdo.expeditedByCountAlone && (d[0] & 0x03U) == 0U &&
                              (d[0] & 0x0CU) != 0U;
      if ((d[0] & 0x02U) != 0U || countAlone) {
        const size_t count = (d[0] & 0x01U) != 0U || countAlone ? 4U - ((d[0] >> 2U) & 3U) : 4U;
        return "SDO download " + entry + " = " + formatValue(index, sub, d + 4, count, local);
      }
      downloading_ = true;
      index_ = index;
      subIndex_ = sub;
      collected_.clear();
      return "SDO download " + entry + " segmented" +
             ((d[0] & 0x01U) != 0U ? ", " + std::to_string(loadU32(d + 4)) + " bytes" : "");
    }
    case 2: return "SDO upload " + entry;
    case 3: return "SDO upload segment request";
    case 4:
      uploading_ = downloading_ = false;
      block_ = Block::kNone;
      return abortText(d, entry);
    case 5:
    case 6: return describeBlockRequest(d, entry);
    default: return "SDO unknown command " + hex32(d[0]);
  }
}

std::string FrameTracer::describeSdoResponse(const CanFrame& frame, bool local) {
  if (frame.rtr || frame.dlc != 8U) {
    return "SDO response (malformed)";
  }
  const uint8_t* d = frame.data;
  if (block_ == Block::kUploadSegments && d[0] != 0x80U) {
    return describeBlockSegment(d);
  }
  const uint16_t index = loadU16(d + 1);
  const uint8_t sub = d[3];
  const std::string entry = entryText(index, sub);
  const std::string name = nameOf(index, sub);
  switch (d[0] >> 5U) {
    case 0: {
      const size_t count = 7U - ((d[0] >> 1U) & 7U);
      const bool last = (d[0] & 1U) != 0U;
      collected_.insert(collected_.end(), d + 1, d + 1 + count);
      std::string text = "SDO upload segment " + formatValue(0, 0, d + 1, count, false);
      if (last && uploading_) {
        text += " (last) " + entryText(index_, subIndex_) + " = " +
                formatValue(index_, subIndex_, collected_.data(), collected_.size(), local);
        uploading_ = false;
      }
      return text;
    }
    case 1: return "SDO download segment response";
    case 2: {
      if ((d[0] & 0x02U) != 0U) {
        const size_t count = (d[0] & 0x01U) != 0U ? 4U - ((d[0] >> 2U) & 3U) : 4U;
        return "SDO upload response " + entry + " " + formatValue(index, sub, d + 4, count, local) +
               (name.empty() ? "" : "  " + name);
      }
      uploading_ = true;
      index_ = index;
      subIndex_ = sub;
      collected_.clear();
      return "SDO upload response " + entry + " segmented, " + std::to_string(loadU32(d + 4)) +
             " bytes" + (name.empty() ? "" : "  " + name);
    }
    case 3: return "SDO download response " + entry + (name.empty() ? "" : "  " + name);
    case 4:
      uploading_ = downloading_ = false;
      block_ = Block::kNone;
      return abortText(d, entry);
    case 5:
    case 6: return describeBlockResponse(d, entry, name);
    default: return "SDO unknown response";
  }
}

std::string FrameTracer::describeBlockSegment(const uint8_t* d) {
  const auto sequence = static_cast<uint8_t>(d[0] & 0x7FU);
  const bool last = (d[0] & 0x80U) != 0U;
  if (last) {
    blockLastSequence_ = sequence;
  }
  return "SDO block segment " + std::to_string(sequence) + " " +
         formatValue(0, 0, d + 1, 7, false) + (last ? " (last)" : "");
}

// Client frames: ccs 6 = block download (cs bit 0: 0 initiate, 1 end); ccs 5 = block upload
// (cs bits 1..0: 0 initiate, 1 end response, 2 acknowledgement, 3 start).
std::string FrameTracer::describeBlockRequest(const uint8_t* d, const std::string& entry) {
  const bool crc = (d[0] & 0x04U) != 0U;
  if ((d[0] >> 5U) == 6U) {
    if ((d[0] & 0x01U) == 0U) {
      block_ = Block::kDownloadSegments;
      blockLastSequence_ = 0;
      return "SDO block download " + entry +
             ((d[0] & 0x02U) != 0U ? ", " + std::to_string(loadU32(d + 4)) + " bytes" : "") +
             (crc ? ", CRC" : "");
    }
    block_ = Block::kNone;
    return "SDO block download end, " + unusedText(d[0]) + ", CRC " + hex16(loadU16(d + 1));
  }
  switch (d[0] & 0x03U) {
    case 0:
      return "SDO block upload " + entry + ", blksize " + std::to_string(d[4]) + ", pst " +
             std::to_string(d[5]) + (crc ? ", CRC" : "");
    case 1: block_ = Block::kNone; return "SDO block upload end response";
    case 2:
      if (blockLastSequence_ != 0U && d[1] == blockLastSequence_) {
        block_ = Block::kUploadEnd;
      }
      blockLastSequence_ = 0;
      return "SDO block upload ack " + std::to_string(d[1]) + ", blksize " + std::to_string(d[2]);
    default:
      block_ = Block::kUploadSegments;
      blockLastSequence_ = 0;
      return "SDO block upload start";
  }
}

// Server frames: scs 5 = block download (ss: 0 initiate, 1 end, 2 acknowledgement); scs 6 =
// block upload (ss bit 0: 0 initiate, 1 end).
std::string FrameTracer::describeBlockResponse(const uint8_t* d, const std::string& entry,
                                               const std::string& name) {
  const bool crc = (d[0] & 0x04U) != 0U;
  if ((d[0] >> 5U) == 5U) {
    switch (d[0] & 0x03U) {
      case 0:
        return "SDO block download response " + entry + ", blksize " + std::to_string(d[4]) +
               (crc ? ", CRC" : "") + (name.empty() ? "" : "  " + name);
      case 1: block_ = Block::kNone; return "SDO block download end response";
      case 2:
        if (blockLastSequence_ != 0U && d[1] == blockLastSequence_) {
          block_ = Block::kDownloadEnd;
        }
        blockLastSequence_ = 0;
        return "SDO block download ack " + std::to_string(d[1]) + ", blksize " +
               std::to_string(d[2]);
      default: return "SDO unknown response";
    }
  }
  if ((d[0] & 0x01U) == 0U) {
    return "SDO block upload response " + entry +
           ((d[0] & 0x02U) != 0U ? ", " + std::to_string(loadU32(d + 4)) + " bytes" : "") +
           (crc ? ", CRC" : "") + (name.empty() ? "" : "  " + name);
  }
  block_ = Block::kNone;
  return "SDO block upload end, " + unusedText(d[0]) + ", CRC " + hex16(loadU16(d + 1));
}

std::string FrameTracer::describeLss(const CanFrame& frame, bool fromMaster) const {
  if (frame.dlc != 8U) {
    return "LSS (malformed)";
  }
  const char* what = nullptr;
  switch (frame.data[0]) {
    case 0x04: what = "switch state global"; break;
    case 0x11: what = "configure node-id"; break;
    case 0x13: what = "configure bit timing"; break;
    case 0x15: what = "activate bit timing"; break;
    case 0x17: what = "store configuration"; break;
    case 0x40: what = "switch state selective vendor-id"; break;
    case 0x41: what = "switch state selective product code"; break;
    case 0x42: what = "switch state selective revision"; break;
    case 0x43: what = "switch state selective serial number"; break;
    case 0x44: what = "switch state selective response"; break;
    case 0x46: what = "identify remote slave vendor-id"; break;
    case 0x47: what = "identify remote slave product code"; break;
    case 0x48: what = "identify remote slave revision low"; break;
    case 0x49: what = "identify remote slave revision high"; break;
    case 0x4A: what = "identify remote slave serial low"; break;
    case 0x4B: what = "identify remote slave serial high"; break;
    case 0x4C: what = "identify non-configured remote slave"; break;
    case 0x4F: what = "identify slave"; break;
    case 0x50: what = "identify non-configured slave"; break;
    case 0x51: what = "fastscan"; break;
    case 0x5A: what = "inquire vendor-id"; break;
    case 0x5B: what = "inquire product code"; break;
    case 0x5C: what = "inquire revision number"; break;
    case 0x5D: what = "inquire serial number"; break;
    case 0x5E: what = "inquire node-id"; break;
    default: what = "unknown command"; break;
  }
  return std::string(fromMaster ? "LSS request " : "LSS response ") + what;
}

}  // namespace costa::host
