#include "sdo_block_client.hpp"

#include <cstdio>
#include <cstring>

#include "costa/crc16.hpp"
#include "costa/od/little_endian.hpp"

namespace costa::test {
namespace {

constexpr size_t kSegment = 7;

uint16_t crcOf(const std::vector<uint8_t>& data) {
  return crc16(data.data(), data.size());
}

}  // namespace

std::string hexBytes(const uint8_t* data, size_t length) {
  std::string text;
  for (size_t i = 0; i < length; ++i) {
    char buffer[4];
    std::snprintf(buffer, sizeof(buffer), i == 0 ? "%02X" : " %02X", data[i]);
    text += buffer;
  }
  return text;
}

void SdoBlockClient::send(std::vector<uint8_t> bytes) {
  bytes.resize(8, 0);
  CanFrame frame;
  frame.id = 0x600U + static_cast<uint32_t>(nodeId_);
  frame.dlc = 8;
  std::memcpy(frame.data, bytes.data(), 8);
  bus_.send(frame);
}

bool SdoBlockClient::next(uint8_t (&data)[8], BlockTransferResult* result) {
  CanFrame frame;
  for (;;) {
    if (!bus_.receive(&frame, timeoutMs_)) {
      result->error = "the server sent nothing";
      return false;
    }
    if (frame.id == 0x580U + static_cast<uint32_t>(nodeId_)) {
      break;  // anything else (heartbeat) is not the client's business
    }
  }
  if (frame.dlc != 8U || frame.rtr || frame.extended) {
    result->error = "malformed SDO response";
    return false;
  }
  std::memcpy(data, frame.data, 8);
  if (data[0] == 0x80U) {
    result->abortCode = loadU32(data + 4);
    return false;
  }
  return true;
}

BlockTransferResult SdoBlockClient::download(uint16_t index, uint8_t subIndex,
                                             const std::vector<uint8_t>& data,
                                             const BlockTransferOptions& options) {
  BlockTransferResult result;
  const auto lo = static_cast<uint8_t>(index);
  const auto hi = static_cast<uint8_t>(index >> 8U);
  const auto size = static_cast<uint32_t>(data.size());
  const uint8_t command =
      static_cast<uint8_t>(0xC0U | (options.crc ? 0x04U : 0U) | (options.sizeIndicated ? 2U : 0U));
  send({command, lo, hi, subIndex, static_cast<uint8_t>(options.sizeIndicated ? size : 0U),
        static_cast<uint8_t>(options.sizeIndicated ? size >> 8U : 0U),
        static_cast<uint8_t>(options.sizeIndicated ? size >> 16U : 0U),
        static_cast<uint8_t>(options.sizeIndicated ? size >> 24U : 0U)});
  uint8_t r[8];
  if (!next(r, &result)) {
    return result;
  }
  if ((r[0] & 0xE3U) != 0xA0U || r[1] != lo || r[2] != hi || r[3] != subIndex) {
    result.error = "bad initiate block download response " + hexBytes(r, 8);
    return result;
  }
  const bool crcUsed = options.crc && (r[0] & 0x04U) != 0U;
  int blockSize = r[4];
  result.blockSizes.push_back(blockSize);
  size_t acknowledged = 0;
  int segmentNumber = 0;
  bool lostOnce = false;
  for (;;) {
    if (blockSize < 1 || blockSize > 127) {
      result.error = "server block size " + std::to_string(blockSize) + " out of 1..127";
      return result;
    }
    int sequence = 0;
    size_t position = acknowledged;
    bool last = false;
    while (!last && sequence < blockSize) {
      ++sequence;
      const size_t count = std::min(kSegment, data.size() - position);
      last = position + count == data.size();
      std::vector<uint8_t> segment = {static_cast<uint8_t>((last ? 0x80 : 0) | sequence)};
      segment.insert(segment.end(), data.begin() + static_cast<long>(position),
                     data.begin() + static_cast<long>(position + count));
      if (segmentNumber++ == options.loseSegment && !lostOnce) {
        lostOnce = true;  // never reaches the server
      } else {
        send(segment);
      }
      position += count;
    }
    if (!next(r, &result)) {
      return result;
    }
    ++result.subBlocks;
    if (r[0] != 0xA2U) {
      result.error = "expected a sub-block acknowledgement, got " + hexBytes(r, 8);
      return result;
    }
    const int ackSequence = r[1];
    if (ackSequence > sequence) {
      result.error = "acknowledged sequence " + std::to_string(ackSequence) + " was never sent";
      return result;
    }
    acknowledged =
        std::min(data.size(), acknowledged + static_cast<size_t>(ackSequence) * kSegment);
    if (result.subBlocks == options.abortAfterSubBlocks) {
      send({0x80, lo, hi, subIndex, 0x00, 0x00, 0x00, 0x08});
      return result;
    }
    if (last && ackSequence == sequence) {
      break;
    }
    blockSize = r[2];
    result.blockSizes.push_back(blockSize);
  }
  const size_t inLast = data.empty() ? 0U : (data.size() - 1U) % kSegment + 1U;
  const auto unused = static_cast<uint8_t>(kSegment - inLast);
  uint16_t crc = crcUsed ? crcOf(data) : 0U;
  if (options.corruptCrc) {
    crc = static_cast<uint16_t>(crc ^ 0x0101U);
  }
  send({static_cast<uint8_t>(0xC1U | (static_cast<unsigned>(unused) << 2U)),
        static_cast<uint8_t>(crc), static_cast<uint8_t>(crc >> 8U)});
  if (!next(r, &result)) {
    return result;
  }
  if (r[0] != 0xA1U) {
    result.error = "expected the end block download response, got " + hexBytes(r, 8);
  }
  return result;
}

BlockTransferResult SdoBlockClient::upload(uint16_t index, uint8_t subIndex,
                                           const BlockTransferOptions& options) {
  BlockTransferResult result;
  const auto lo = static_cast<uint8_t>(index);
  const auto hi = static_cast<uint8_t>(index >> 8U);
  send({static_cast<uint8_t>(0xA0U | (options.crc ? 0x04U : 0U)), lo, hi, subIndex,
        options.blockSize, options.protocolSwitch});
  uint8_t r[8];
  if (!next(r, &result)) {
    return result;
  }
  if ((r[0] >> 5U) == 2U) {
    normalUpload(r, &result);
    return result;
  }
  if ((r[0] & 0xE1U) != 0xC0U || r[1] != lo || r[2] != hi || r[3] != subIndex) {
    result.error = "bad initiate block upload response " + hexBytes(r, 8);
    return result;
  }
  // Costa's rule: when its initiate response sets sc, the end frame carries the valid CRC,
  // whether this client asked for one (cc) or not; without sc it carries 0.
  const bool crcUsed = (r[0] & 0x04U) != 0U;
  const bool sized = (r[0] & 0x02U) != 0U;
  const uint32_t size = loadU32(r + 4);
  send({0xA3});
  int segmentNumber = 0;
  bool lostOnce = false;
  bool complete = false;
  while (!complete) {
    int good = 0;
    bool dropping = false;
    for (;;) {
      if (!next(r, &result)) {
        return result;
      }
      const int sequence = r[0] & 0x7F;
      const bool last = (r[0] & 0x80U) != 0U;
      if (sequence < 1 || sequence > options.blockSize) {
        result.error = "segment sequence number " + std::to_string(sequence) + " out of range";
        return result;
      }
      const bool lost = segmentNumber++ == options.loseSegment && !lostOnce;
      lostOnce = lostOnce || lost;
      if (!lost && !dropping && sequence == good + 1) {
        good = sequence;
        result.data.insert(result.data.end(), r + 1, r + 8);
        complete = last;
      } else {
        dropping = true;
      }
      if (last || sequence == options.blockSize) {
        break;
      }
    }
    ++result.subBlocks;
    if (result.subBlocks == options.abortAfterSubBlocks) {
      send({0x80, lo, hi, subIndex, 0x00, 0x00, 0x00, 0x08});
      return result;
    }
    send({0xA2, static_cast<uint8_t>(good), options.blockSize});
  }
  if (!next(r, &result)) {
    return result;
  }
  if ((r[0] & 0xE3U) != 0xC1U) {
    result.error = "expected the end block upload request, got " + hexBytes(r, 8);
    return result;
  }
  const size_t unused = (r[0] >> 2U) & 0x07U;
  result.data.resize(result.data.size() - unused);
  const uint16_t crc = loadU16(r + 1);
  if (crcUsed && crc != crcOf(result.data)) {
    result.error = "CRC mismatch";
  } else if (!crcUsed && crc != 0U) {
    result.error = "CRC sent although the server did not announce CRC support";
  } else if (sized && size != result.data.size()) {
    result.error = "indicated " + std::to_string(size) + " bytes, received " +
                   std::to_string(result.data.size());
  }
  send({0xA1});
  return result;
}

void SdoBlockClient::normalUpload(const uint8_t (&first)[8], BlockTransferResult* result) {
  result->switchedProtocol = true;
  if ((first[0] & 0x02U) != 0U) {  // expedited
    const size_t count = (first[0] & 0x01U) != 0U ? 4U - ((first[0] >> 2U) & 0x03U) : 4U;
    result->data.assign(first + 4, first + 4 + count);
    return;
  }
  uint8_t toggle = 0;
  uint8_t r[8];
  for (;;) {
    send({static_cast<uint8_t>(0x60U | (static_cast<unsigned>(toggle) << 4U))});
    if (!next(r, result)) {
      return;
    }
    if ((r[0] & 0xE0U) != 0U || ((r[0] >> 4U) & 1U) != toggle) {
      result->error = "bad upload segment " + hexBytes(r, 8);
      return;
    }
    const size_t count = kSegment - ((r[0] >> 1U) & 0x07U);
    result->data.insert(result->data.end(), r + 1, r + 1 + count);
    if ((r[0] & 0x01U) != 0U) {
      return;
    }
    toggle ^= 1U;
  }
}

}  // namespace costa::test
