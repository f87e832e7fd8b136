// libFuzzer target: lib/io's reader of output documents (json_reader.h, `shpack eval`) given
// arbitrary bytes. The bytes go to an in-memory file (memfd) read through its /proc path, so
// each run touches no disk. Properties: no crash, no sanitizer report, no exception out of
// read_sh_json; on success every coefficient is finite and the floats are finite float32s
// (what json_reader.h checks); on failure the message names the file.
#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "shpack/io/json_reader.h"

namespace {

int memory_file() {
  static const int fd = memfd_create("shpack_fuzz_json", 0);
  return fd;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const int fd = memory_file();
  if (fd < 0 || ftruncate(fd, 0) != 0) std::abort();
  std::size_t written = 0;
  while (written < size) {
    const ssize_t n = pwrite(fd, data + written, size - written, static_cast<off_t>(written));
    if (n <= 0) std::abort();
    written += static_cast<std::size_t>(n);
  }
  const std::string path = "/proc/self/fd/" + std::to_string(fd);
  shpack::io::ShJsonContent content;
  const shpack::io::IoStatus st = shpack::io::read_sh_json(path, content);
  if (!st.ok()) {
    if (st.message.rfind(path + ": ", 0) != 0 || st.message.find('\n') != std::string::npos) std::abort();
    return 0;
  }
  for (int c = 0; c < shpack::kChannelCount; ++c)
    for (int i = 0; i < shpack::kShCount; ++i)
      if (!std::isfinite(content.radiance.c[c][i]) || !std::isfinite(content.unity_sh[c][i])) std::abort();
  for (const auto* v : {&content.shader.SHAr, &content.shader.SHAg, &content.shader.SHAb, &content.shader.SHBr,
                        &content.shader.SHBg, &content.shader.SHBb, &content.shader.SHC})
    for (float x : *v)
      if (!std::isfinite(x)) std::abort();
  return 0;
}
