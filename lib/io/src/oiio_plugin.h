// oiio_plugin.h (private) - shpack's OpenImageIO module (oiio_plugin_abi.h), opened on
// first use and kept for the life of the process.
//
// The module is looked for beside the shared object lib/io is linked into when that is not
// the executable (the Python module, whose build puts the module beside it), then beside the
// running executable (/proc/self/exe), where the build puts it, then in SHPACK_PLUGIN_RELDIR
// relative to the executable's folder, where `cmake --install` puts it (<prefix>/lib/shpack
// beside <prefix>/bin). No other path is compiled in.
#pragma once

#include <string>

#include "oiio_plugin_abi.h"

namespace shpack::io::detail {

struct OiioPlugin {
  OiioOpenFn* open = nullptr;
  OiioEncodePngFn* encode_png = nullptr;
  OiioRenderTextFn* render_text = nullptr;
};

// The module's entry points, or null with the problem in `problem`: a clause to follow
// "<format> is read through OpenImageIO: ", saying where the module was looked for or why
// it could not be used. Thread-safe; the module is opened once.
const OiioPlugin* oiio_plugin(std::string& problem);

}  // namespace shpack::io::detail
