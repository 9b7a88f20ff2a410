// A small SDO client for tests: block download and block upload (CiA 301 7.2.4.3.9-17) over a
// TranscriptBus, checking every server frame, with faults to inject.
#pragma once

#include <stdint.h>

#include <string>
#include <vector>

#include "transcript_player.hpp"

namespace costa::test {

struct BlockTransferOptions {
  bool crc = true;               ///< Client CRC support (cc).
  bool sizeIndicated = true;     ///< Download: announce the size.
  uint8_t blockSize = 127;       ///< Upload: block size the client asks for.
  uint8_t protocolSwitch = 0;    ///< Upload: pst.
  int loseSegment = -1;          ///< Segment (0-based, counting every segment frame of the
                                 ///< transfer) the client does not send (download) or treats as
                                 ///< lost (upload), once.
  bool corruptCrc = false;       ///< Download: send a wrong CRC in the end frame.
  int abortAfterSubBlocks = -1;  ///< Abort (0x08000000) after this many sub-blocks.
};

struct BlockTransferResult {
  uint32_t abortCode = 0;         ///< The server's abort code, 0 when none.
  std::string error;              ///< What the server did wrong, "" when nothing.
  std::vector<uint8_t> data;      ///< Upload: the value.
  bool switchedProtocol = false;  ///< Upload: the server answered as a normal upload (pst).
  std::vector<int> blockSizes;    ///< Block sizes the server asked for (download).
  int subBlocks = 0;              ///< Sub-blocks transferred (repeated ones included).
  bool ok() const { return abortCode == 0U && error.empty(); }
};

class SdoBlockClient {
 public:
  /// `timeoutMs`: how long to wait for each server frame (0 in virtual time).
  SdoBlockClient(TranscriptBus& bus, int nodeId, int timeoutMs = 0)
      : bus_(bus), nodeId_(nodeId), timeoutMs_(timeoutMs) {}

  BlockTransferResult download(uint16_t index, uint8_t subIndex, const std::vector<uint8_t>& data,
                               const BlockTransferOptions& options = {});
  BlockTransferResult upload(uint16_t index, uint8_t subIndex,
                             const BlockTransferOptions& options = {});

 private:
  void send(std::vector<uint8_t> bytes);
  /// The server's next SDO frame; false (with `result->error`) when none or malformed, or with
  /// `result->abortCode` when it is an abort.
  bool next(uint8_t (&data)[8], BlockTransferResult* result);
  void normalUpload(const uint8_t (&first)[8], BlockTransferResult* result);

  TranscriptBus& bus_;
  int nodeId_;
  int timeoutMs_;
};

std::string hexBytes(const uint8_t* data, size_t length);

}  // namespace costa::test
