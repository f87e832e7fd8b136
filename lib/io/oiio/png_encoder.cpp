// The OpenImageIO module's PNG encoder (oiio_plugin_abi.h), for shpack preview's pictures.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <exception>
#include <memory>

#include "oiio_plugin_abi.h"

extern "C" bool shpack_oiio_encode_png(std::uint32_t width, std::uint32_t height, const std::uint8_t* rgb,
                                       std::vector<unsigned char>* bytes, std::string* error) {
  try {
    // Encoded in memory (an OpenImageIO IOProxy); the caller writes the file.
    OIIO::Filesystem::IOVecOutput memory(*bytes);
    const std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create("png");
    if (!out) {
      *error = "no PNG writer (" + OIIO::geterror() + ")";
      return false;
    }
    OIIO::ImageSpec spec(static_cast<int>(width), static_cast<int>(height), 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    spec.attribute("png:compressionLevel", 9);  // the gallery keeps its images small
    if (!out->set_ioproxy(&memory) || !out->open("memory.png", spec) || !out->write_image(OIIO::TypeDesc::UINT8, rgb) ||
        !out->close()) {
      *error = "cannot encode the PNG (" + out->geterror() + ")";
      return false;
    }
    return true;
  } catch (const std::exception& e) {
    *error = e.what();
    return false;
  }
}
