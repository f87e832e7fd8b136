// libFuzzer target: lib/io's image readers given arbitrary files (map_source.h, image_file.h):
// the header paths (open: part, channels, windows, the texel budget) and, for what opens, the
// decode of the whole image. Files that start with OpenEXR's magic number go to OpenEXR's own
// reader (lib/io/src/exr_decoder.h, after the header walk of image_open.h), those that start
// with a Radiance or PFM magic line to shpack's own readers (hdr_decoder.h, pfm_decoder.h;
// fuzz_float_maps.cpp reads them in bands too), the rest to the OpenImageIO module (beside
// this executable; tests/fuzz/CMakeLists.txt puts it there). The first byte chooses the file's
// extension, which OpenImageIO goes by: .exr, .hdr, .pfm or .png; the rest is the file,
// written to a scratch folder in /dev/shm (no disk). The budget is 2^16 texels, so that
// nothing a header declares may take more than a few MB; the target runs with
// -rss_limit_mb=512 (set in LLVMFuzzerInitialize, after any flag on the command line).
// Properties: no crash, no sanitizer report, no exception out of the readers, no run past the
// RSS limit or libFuzzer's timeout; a failure is one line that starts with the file's name.
// (That no reason is ever an empty "()" is tested in tests/io/hostile_inputs_test.cpp: here
// the messages quote the file's own names and channels, which may hold "()".) Leaks inside
// libOpenImageIO are suppressed (see __lsan_default_suppressions below).
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "fuzz_scratch.h"
#include "shpack/io/image_file.h"
#include "shpack/io/map_source.h"

namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kFuzzMaxTexels = std::uint64_t{1} << 16;

const fs::path& scratch() {
  static const fs::path dir = shpack_fuzz::make_scratch("image_header");
  return dir;
}

void check_failure(const shpack::io::IoStatus& st, const fs::path& path) {
  if (st.ok()) return;
  if (st.message.rfind(path.string() + ": ", 0) != 0 || st.message.find('\n') != std::string::npos) std::abort();
}

}  // namespace

// OpenImageIO's PNG reader leaks a few strings when libpng longjmps out of a broken header
// (the jump skips their destructors; libOpenImageIO 2.4, not shpack's code): those leaks
// are not reported. Any other leak is.
extern "C" const char* __lsan_default_suppressions() { return "leak:libOpenImageIO.so\n"; }

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  static std::vector<char*> args;
  static char rss_limit[] = "-rss_limit_mb=512";
  args.assign(*argv, *argv + *argc);
  args.push_back(rss_limit);
  args.push_back(nullptr);
  *argc = static_cast<int>(args.size()) - 1;
  *argv = args.data();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static constexpr std::array<const char*, 4> kNames = {"in.exr", "in.hdr", "in.pfm", "in.png"};
  const fs::path path = scratch() / kNames[data[0] % kNames.size()];
  shpack_fuzz::write_input(path, data + 1, size - 1);

  shpack::io::SourceOptions options;
  options.layout = shpack::Layout::Equirect;  // any shape: the layout is not what is fuzzed
  options.max_texels = kFuzzMaxTexels;
  {
    shpack::io::MapSource source;
    const shpack::io::IoStatus st = source.open(path, options);
    check_failure(st, path);
    if (st.ok()) {
      const shpack::io::SourceInfo& info = source.info();
      if (std::uint64_t{info.width} * info.height > kFuzzMaxTexels) std::abort();
      shpack::MapImage map;
      check_failure(source.read_whole(map, 1), path);
    }
  }
  shpack::io::ImageFile image;
  const shpack::io::IoStatus st = shpack::io::read_image_file(path, std::string(), kFuzzMaxTexels, image);
  check_failure(st, path);
  if (st.ok() && image.pixels.size() != std::size_t{image.width} * image.height * image.channels) std::abort();
  return 0;
}
