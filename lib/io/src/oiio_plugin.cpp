#include "oiio_plugin.h"

#include <dlfcn.h>

#include <filesystem>
#include <system_error>
#include <vector>

namespace shpack::io::detail {
namespace {

namespace fs = std::filesystem;

// An address inside this shared object, for dladdr.
constexpr char kOwnModuleMarker = 0;

struct Loaded {
  OiioPlugin plugin;
  bool ok = false;
  std::string problem;
};

template <class Fn>
Fn* symbol(void* module, const char* name) {
  return reinterpret_cast<Fn*>(::dlsym(module, name));
}

// Opens the module at `file`; false with the reason in `why`.
bool load(const fs::path& file, OiioPlugin& plugin, std::string& why) {
  void* module = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (module == nullptr) {
    const char* error = ::dlerror();
    why = error != nullptr ? error : "cannot be opened";
    return false;
  }
  auto* abi = symbol<OiioAbiFn>(module, "shpack_oiio_abi");
  plugin.open = symbol<OiioOpenFn>(module, "shpack_oiio_open");
  plugin.encode_png = symbol<OiioEncodePngFn>(module, "shpack_oiio_encode_png");
  plugin.render_text = symbol<OiioRenderTextFn>(module, "shpack_oiio_render_text");
  if (abi == nullptr || plugin.open == nullptr || plugin.encode_png == nullptr || plugin.render_text == nullptr ||
      abi() != kOiioPluginAbi) {
    ::dlclose(module);
    why = file.string() + " is from another build of shpack";
    return false;
  }
  return true;  // never closed: decoders made by it may live until exit
}

// The folder of the shared object this code is linked into, when it is not the executable
// (lib/io inside the Python module, python/CMakeLists.txt); empty otherwise.
fs::path own_module_folder(const fs::path& exe) {
  Dl_info info{};
  if (::dladdr(&kOwnModuleMarker, &info) == 0 || info.dli_fname == nullptr)
    return {};
  std::error_code ec;
  const fs::path module = fs::canonical(info.dli_fname, ec);
  if (ec || module == fs::canonical(exe, ec)) return {};
  return module.parent_path();
}

Loaded find_and_load() {
  Loaded loaded;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) {
    loaded.problem = "shpack's OpenImageIO module cannot be found (no /proc/self/exe)";
    return loaded;
  }
  const fs::path beside = exe.parent_path() / kOiioPluginFile;
  const fs::path installed = (exe.parent_path() / SHPACK_PLUGIN_RELDIR / kOiioPluginFile).lexically_normal();
  const fs::path module_folder = own_module_folder(exe);
  std::vector<fs::path> candidates = {beside, installed};
  if (!module_folder.empty()) candidates.insert(candidates.begin(), module_folder / kOiioPluginFile);
  std::string why;
  for (const fs::path& file : candidates) {
    if (!fs::exists(file, ec)) continue;
    loaded.ok = load(file, loaded.plugin, why);
    if (loaded.ok) return loaded;
    loaded.problem = "shpack's OpenImageIO module cannot be used (" + why + ")";
    return loaded;
  }
  loaded.problem = std::string("shpack's OpenImageIO module ").append(kOiioPluginFile);
  if (module_folder.empty()) {
    loaded.problem.append(" is in neither ").append(exe.parent_path().string());
    loaded.problem.append(" nor ").append(installed.parent_path().string());
  } else {
    loaded.problem.append(" is in none of ").append(module_folder.string()).append(", ");
    loaded.problem.append(exe.parent_path().string()).append(" and ").append(installed.parent_path().string());
  }
  return loaded;
}

}  // namespace

const OiioPlugin* oiio_plugin(std::string& problem) {
  static const Loaded loaded = find_and_load();
  if (!loaded.ok) problem = loaded.problem;
  return loaded.ok ? &loaded.plugin : nullptr;
}

}  // namespace shpack::io::detail
