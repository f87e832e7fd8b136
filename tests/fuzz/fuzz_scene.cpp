// libFuzzer target: lib/scene's scene reader (scene_loader.h, `shpack bake`) given arbitrary
// bytes, through an in-memory file (memfd) read by its /proc path. Files a scene names are
// resolved against /proc/self/fd, so they are missing (an error like any other).
// Properties: no crash, no sanitizer report, no exception out of load_scene; an error is one
// line naming the scene file.
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "shpack/scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const int fd = memfd_create("shpack_fuzz_scene", 0);
  if (fd < 0 || ftruncate(fd, 0) != 0) std::abort();
  for (std::size_t written = 0; written < size;) {
    const ssize_t n = pwrite(fd, data + written, size - written, static_cast<off_t>(written));
    if (n <= 0) std::abort();
    written += static_cast<std::size_t>(n);
  }
  const std::string path = "/proc/self/fd/" + std::to_string(fd);
  shpack::scene::Scene scene;
  const shpack::io::IoStatus st = shpack::scene::load_scene(path, scene);
  if (!st.ok() && (st.message.rfind(path, 0) != 0 || st.message.find('\n') != std::string::npos)) std::abort();
  return 0;
}
