#include "support/guarded_buffer.h"

#include <sys/mman.h>
#include <unistd.h>

namespace shpack_test {

GuardedBuffer::GuardedBuffer(std::size_t size, Guard guard) : size_(size) {
  const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  const std::size_t body = (size + page - 1) / page * page;
  map_size_ = body + page;
  void* m = mmap(nullptr, map_size_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (m == MAP_FAILED) return;
  map_ = m;
  std::byte* base = static_cast<std::byte*>(m);
  if (guard == Guard::After) {
    if (mprotect(base + body, page, PROT_NONE) != 0) return;
    data_ = base + body - size;
  } else {
    if (mprotect(base, page, PROT_NONE) != 0) return;
    data_ = base + page;
  }
}

GuardedBuffer::~GuardedBuffer() {
  if (map_ != nullptr) munmap(map_, map_size_);
}

}  // namespace shpack_test
