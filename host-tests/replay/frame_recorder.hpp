// The replayer's CAN controller: keeps the frames the node sends until the transcript reads
// them, in order, and tells a listener (the report) of every frame as it is sent.
#pragma once

#include <stddef.h>

#include "costa/port/can_port.hpp"

namespace costa::replay {

/// Told of every frame the recorder accepts.
class FrameListener {
 public:
  virtual void onSent(const CanFrame& frame) noexcept { (void)frame; }

 protected:
  FrameListener() = default;
  ~FrameListener() = default;
  FrameListener(const FrameListener&) = default;
  FrameListener& operator=(const FrameListener&) = default;
};

/// Accepts every frame while fewer than kCapacity are unread (as InProcessBus's RecordingCan
/// accepts every frame of a transcript); a frame beyond that is refused and the recorder marks
/// itself overflowed, which fails the replay: the node would behave differently from the host.
class FrameRecorder final : public CanTransmitter {
 public:
  static constexpr size_t kCapacity = 256;

  explicit FrameRecorder(FrameListener* listener = nullptr) noexcept : listener_(listener) {}

  bool tryTransmit(const CanFrame& frame) noexcept override;

  /// The oldest unread frame; false when every frame has been read.
  bool next(CanFrame* frame) noexcept;
  /// A frame was refused because kCapacity frames were unread.
  bool overflowed() const noexcept { return overflowed_; }
  /// Frames accepted since construction or reset().
  size_t sent() const noexcept { return sent_; }
  /// Forgets every frame (a new transcript).
  void reset() noexcept;

 private:
  FrameListener* listener_;
  CanFrame frames_[kCapacity];
  size_t first_ = 0;  ///< index of the oldest unread frame
  size_t unread_ = 0;
  size_t sent_ = 0;
  bool overflowed_ = false;
};

}  // namespace costa::replay
