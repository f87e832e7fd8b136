// guarded_buffer.h - memory with an inaccessible page right after (or before) it, so a read
// of even one byte outside the buffer crashes the test (in any build, not only under ASan).
#pragma once

#include <cstddef>

namespace shpack_test {

class GuardedBuffer {
 public:
  enum class Guard { After, Before };
  // `size` usable bytes; with Guard::After they end exactly at a PROT_NONE page, with
  // Guard::Before they start exactly after one.
  GuardedBuffer(std::size_t size, Guard guard);
  ~GuardedBuffer();
  GuardedBuffer(const GuardedBuffer&) = delete;
  GuardedBuffer& operator=(const GuardedBuffer&) = delete;

  std::byte* data() const { return data_; }
  std::size_t size() const { return size_; }
  bool ok() const { return data_ != nullptr; }

 private:
  void* map_ = nullptr;
  std::size_t map_size_ = 0;
  std::byte* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace shpack_test
