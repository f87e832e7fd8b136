// shpack_decode_only IMAGE: opens the image with OpenImageIO, reads every pixel as float and
// exits. The floor that the whole `shpack convert` process is measured against
// (bench/convert_vs_decode.sh): what any tool that reads the file must spend.
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <memory>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: shpack_decode_only IMAGE\n");
    return 2;
  }
  const std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(argv[1]);
  if (!in) {
    std::fprintf(stderr, "shpack_decode_only: %s: %s\n", argv[1], OIIO::geterror().c_str());
    return 1;
  }
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<float> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data())) {
    std::fprintf(stderr, "shpack_decode_only: %s: %s\n", argv[1], in->geterror().c_str());
    return 1;
  }
  return 0;
}
