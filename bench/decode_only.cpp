// shpack_decode_only IMAGE [THREADS]: decodes the R, G, B channels of an OpenEXR file as
// float with OpenEXR itself, on THREADS threads of OpenEXR's pool (default: one per core),
// sums them (so that nothing is optimised away) and exits. The floor that the whole
// `shpack convert` process is measured against (bench/convert_vs_decode.sh): what any tool
// that reads the file must spend, with no SH, no hash and no output.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfThreading.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <thread>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    std::fprintf(stderr, "usage: shpack_decode_only IMAGE [THREADS]\n");
    return 2;
  }
  const int threads = argc == 3 ? std::atoi(argv[2]) : static_cast<int>(std::thread::hardware_concurrency());
  try {
    Imf::setGlobalThreadCount(threads);
    Imf::InputFile file(argv[1], threads);
    const Imath::Box2i window = file.header().dataWindow();
    const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
    const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
    std::vector<float> pixels(static_cast<std::size_t>(width * height * 3));
    Imf::FrameBuffer frame;
    const char* names[] = {"R", "G", "B"};
    for (int k = 0; k < 3; ++k)
      frame.insert(names[k], Imf::Slice::Make(Imf::FLOAT, pixels.data() + k, window, 3 * sizeof(float),
                                              static_cast<std::size_t>(width) * 3 * sizeof(float)));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    double sum = 0;
    for (const float v : pixels) sum += v;
    std::printf("%.17g\n", sum);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shpack_decode_only: %s: %s\n", argv[1], e.what());
    return 1;
  }
  return 0;
}
