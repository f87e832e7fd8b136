// shpack_module.cpp - the extension `shpack._shpack` (pybind11) of the Python package `shpack`
// (python/shpack/__init__.py re-exports it): `shpack.project(array, ...)` on
// a NumPy array in memory and `shpack.convert(path, ...)` on a file, each returning the
// document `shpack convert` writes, as a dict (json.loads of the same JSON text).
//
// This file only translates, as cli/convert_command.cpp does for the command line: Python
// values into the core's ConvertRequest (convert_request.h) and the names of
// option_choices.h, the array into image views (image_view.h), and lib/io's IoStatus into
// exceptions. The numbers are the pipeline's (convert_pixels.h, convert.h), so they are the
// command's bit for bit, and the messages are the command's lines without "shpack: ": an
// option is named by its flag (--extract-lights is extract_lights=).
//
// Exceptions: ValueError for a bad option or array, or for pixels the pipeline refuses (NaN
// under nonfinite="error", a shape no layout fits, a result too bright for float32);
// convert() raises FileNotFoundError or OSError for a file that cannot be read and
// RuntimeError for one that shpack cannot use. The GIL is released while converting.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "shpack/convert_request.h"
#include "shpack/io/convert.h"
#include "shpack/io/convert_pixels.h"
#include "shpack/io/error_remedy.h"
#include "shpack/io/json_writer.h"
#include "shpack/io/version.h"
#include "shpack/option_choices.h"

namespace py = pybind11;

namespace shpack::python {
namespace {

// What errors name in place of a file: the array argument.
constexpr const char* kArrayName = "array";

// project()'s one layout beyond --layout's: six faces in one (6, N, N, C) array.
constexpr std::array<OptionChoice<Layout>, 1> kFacesChoice = {{{"faces", Layout::Faces}}};

// The pixels as the pipeline reads them: C-contiguous float32 (forcecast converts on ensure).
using Pixels = py::array_t<float, py::array::c_style | py::array::forcecast>;

[[noreturn]] void raise(PyObject* type, const std::string& message) {
  PyErr_SetString(type, message.c_str());
  throw py::error_already_set();
}

// "--OPTION: TEXT not in {a,b,...}", as the command line's parser says it.
template <class Enum, std::size_t N>
Enum choice(const std::array<OptionChoice<Enum>, N>& choices, std::string_view option, const std::string& text) {
  if (const OptionChoice<Enum>* found = find_choice(choices, text)) return found->value;
  std::string line(option);
  raise(PyExc_ValueError, line.append(": ").append(text).append(" not in ").append(choice_list(choices)));
}

// ValueError "--OPTION: 'VALUE' is not WHAT", as the command line's validators say it.
[[noreturn]] void refuse_value(std::string_view option, const py::object& value, std::string_view what) {
  std::string line(option);
  raise(PyExc_ValueError, line.append(": '").append(std::string(py::str(value))).append("' is not ").append(what));
}

// A Python integer (or anything with __index__, such as numpy.int64) as an unsigned value of
// at most `max`; otherwise refuse_value.
std::uint64_t unsigned_value(const py::object& value, std::string_view option, std::string_view what,
                             std::uint64_t max) {
  PyObject* index = PyNumber_Index(value.ptr());
  if (index == nullptr) {
    PyErr_Clear();
    refuse_value(option, value, what);
  }
  const unsigned long long number = PyLong_AsUnsignedLongLong(index);
  Py_DECREF(index);
  if (PyErr_Occurred() != nullptr) {  // negative, or beyond 64 bits
    PyErr_Clear();
    refuse_value(option, value, what);
  }
  if (number > max) refuse_value(option, value, what);
  return number;
}

unsigned unsigned_option(const py::object& value, std::string_view option) {
  return static_cast<unsigned>(
      unsigned_value(value, option, "an unsigned integer", std::numeric_limits<unsigned>::max()));
}

// The options every conversion takes, as Python gives them.
struct Options {
  std::string method, nonfinite, negative, window, cube_frame, colorspace, frame;
  py::object seed, extract_lights, threads;
  double intensity, exposure, rotate;
  bool l1, extract_sun;
};

// The settings of the pipeline, and the frame of the document's radiance_sh, from the options:
// the names through option_choices.h, the rest through to_convert_options.
struct Translated {
  io::ConvertSettings settings;
  EngineFrame frame = EngineFrame::Unity;
};

Translated translate(const Options& options, Layout layout) {
  ConvertRequest request;
  request.method = options.method;
  if (!options.seed.is_none()) request.seed = unsigned_value(options.seed, "--seed", "an unsigned integer",
                                                             std::numeric_limits<std::uint64_t>::max());
  request.nonfinite = choice(kNonFiniteChoices, "--nonfinite", options.nonfinite);
  request.negative = choice(kNegativeChoices, "--negative", options.negative);
  request.intensity = options.intensity;
  request.exposure = options.exposure;
  request.rotate_deg = options.rotate;
  request.window = options.window;
  request.l1 = options.l1;
  request.extract_sun = options.extract_sun;
  request.extract_lights = static_cast<unsigned>(unsigned_value(
      options.extract_lights, "--extract-lights",
      std::string("an integer from 0 to ").append(std::to_string(kMaxExtractedLights)), kMaxExtractedLights));
  request.threads = unsigned_option(options.threads, "--threads");
  Translated out;
  if (const std::string problem = to_convert_options(request, out.settings.convert); !problem.empty())
    raise(PyExc_ValueError, problem);
  out.settings.source.layout = layout;
  out.settings.source.cube_frame = choice(kCubeFrameChoices, "--cube-frame", options.cube_frame);
  out.settings.source.colorspace = choice(kColorSpaceChoices, "--colorspace", options.colorspace);
  out.frame = choice(kEngineFrameChoices, "--frame", options.frame);
  return out;
}

// The exception of a failed conversion: every failure of pixels in memory is the values'
// (ValueError); a file's may be the file's.
[[noreturn]] void raise_failure(const io::IoStatus& st, Layout requested, bool file) {
  const std::string line = io::with_remedy(st, requested);
  switch (st.code) {
    case io::IoErrc::NotFound: raise(file ? PyExc_FileNotFoundError : PyExc_ValueError, line);
    case io::IoErrc::NotAFile:
    case io::IoErrc::Unreadable:
    case io::IoErrc::WriteFailed: raise(file ? PyExc_OSError : PyExc_ValueError, line);
    case io::IoErrc::Unsupported:
    case io::IoErrc::BadDocument: raise(file ? PyExc_RuntimeError : PyExc_ValueError, line);
    case io::IoErrc::Core: raise(PyExc_RuntimeError, line);
    default: raise(PyExc_ValueError, line);
  }
}

// The document as `shpack convert` writes it, parsed by Python's json module.
py::object document_dict(ShDocument& doc, EngineFrame frame) {
  doc.radiance_frame = frame;
  const std::string json = io::to_json(doc);
  return py::module_::import("json").attr("loads")(json);
}

// "(4, 8, 3)"
std::string shape_text(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t k = 0; k < array.ndim(); ++k) {
    if (k > 0) text.append(", ");
    text.append(std::to_string(array.shape(k)));
  }
  return text.append(array.ndim() == 1 ? ",)" : ")");
}

// The layout argument of project(): a name of --layout, or "faces" for a (6, N, N, C) array.
Layout layout_of(const std::string& text) {
  if (find_choice(kFacesChoice, text) != nullptr) return Layout::Faces;
  if (const OptionChoice<Layout>* found = find_choice(kLayoutChoices, text)) return found->value;
  std::string list = choice_list(kLayoutChoices);
  list.insert(list.size() - 1, ",faces");
  raise(PyExc_ValueError, std::string("--layout: ").append(text).append(" not in ").append(list));
}

// The array as C-contiguous float32: float16 and float64 are converted (float16 exactly;
// float64 rounded to nearest, as a float file would hold it), other dtypes refused.
Pixels float32_pixels(const py::object& object) {
  const py::array array = py::array::ensure(object);
  if (!array) raise(PyExc_ValueError, std::string(kArrayName).append(": not a NumPy array"));
  const py::dtype dtype = array.dtype();
  const bool supported = dtype.kind() == 'f' && (dtype.itemsize() == 2 || dtype.itemsize() == 4 || dtype.itemsize() == 8);
  if (!supported) {
    raise(PyExc_ValueError, std::string(kArrayName)
                                .append(": dtype ")
                                .append(std::string(py::str(static_cast<const py::handle&>(dtype))))
                                .append(" is not float16, float32 or float64"));
  }
  return Pixels::ensure(array);
}

// Image rows x columns x channels of the array, checked to fit an ImageView.
struct Shape {
  std::uint32_t faces = 1, height = 0, width = 0, channels = 0;
};

Shape shape_of(const py::array& array, Layout layout) {
  const auto refuse = [&](std::string_view why) {
    raise(PyExc_ValueError,
          std::string(kArrayName).append(": shape ").append(shape_text(array)).append(" ").append(why));
  };
  const py::ssize_t ndim = array.ndim();
  const bool faces = layout == Layout::Faces || (layout == Layout::Auto && ndim == 4);
  if (faces && ndim != 4) refuse("is not (6, N, N, C), the six faces of layout 'faces'");
  if (!faces && ndim == 4) refuse("is six faces (6, N, N, C): give layout 'faces' or 'auto'");
  if (ndim < 2 || ndim > 4) refuse("is not (H, W), (H, W, C) or, for layout 'faces', (6, N, N, C)");
  const py::ssize_t first = faces ? 1 : 0;
  if (faces && array.shape(0) != static_cast<py::ssize_t>(kCubeFaceCount))
    refuse("is not six faces (6, N, N, C) in Unity's order +X -X +Y -Y +Z -Z");
  const py::ssize_t height = array.shape(first), width = array.shape(first + 1);
  const py::ssize_t channels = ndim > first + 2 ? array.shape(first + 2) : 1;
  if (height == 0 || width == 0 || channels == 0) refuse("has no texels");
  constexpr auto kMax = static_cast<py::ssize_t>(std::numeric_limits<std::uint32_t>::max());
  if (height > kMax || width > kMax || channels > kMax) refuse("has a dimension beyond 2^32 - 1");
  if (faces && height != width) refuse("has faces that are not square");
  return {faces ? static_cast<std::uint32_t>(kCubeFaceCount) : 1u, static_cast<std::uint32_t>(height),
          static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(channels)};
}

py::object project(const py::object& object, const std::string& layout_text, const Options& options) {
  const Layout requested = layout_of(layout_text);
  const Pixels pixels = float32_pixels(object);
  const Shape shape = shape_of(pixels, requested);
  Translated translated = translate(options, shape.faces > 1 ? Layout::Faces : requested);
  const float* data = pixels.data();
  ShDocument doc;
  io::IoStatus st;
  {
    const py::gil_scoped_release unlocked;  // `pixels` keeps the memory alive meanwhile
    if (shape.faces == 1) {
      st = io::convert_pixels(make_view(data, shape.width, shape.height, shape.channels), kArrayName,
                              translated.settings, doc);
    } else {
      std::array<ImageView, kCubeFaceCount> faces;
      const std::size_t face_floats = std::size_t{shape.width} * shape.height * shape.channels;
      for (std::size_t f = 0; f < kCubeFaceCount; ++f)
        faces[f] = make_view(data + f * face_floats, shape.width, shape.height, shape.channels);
      st = io::convert_pixel_faces(faces, kArrayName, translated.settings, doc);
    }
  }
  if (!st.ok()) raise_failure(st, requested, false);
  return document_dict(doc, translated.frame);
}

py::object convert(const std::filesystem::path& path, const std::string& layout_text, const Options& options,
                   const py::object& layer, const py::object& max_texels) {
  const Layout layout = choice(kLayoutChoices, "--layout", layout_text);
  Translated translated = translate(options, layout);
  if (!layer.is_none()) translated.settings.source.layer = py::cast<std::string>(layer);
  if (!max_texels.is_none()) {
    constexpr std::string_view kWhat = "an integer from 1 to 18446744073709551615";
    const std::uint64_t budget =
        unsigned_value(max_texels, "--max-texels", kWhat, std::numeric_limits<std::uint64_t>::max());
    if (budget == 0) refuse_value("--max-texels", max_texels, kWhat);
    translated.settings.source.max_texels = budget;
  }
  ShDocument doc;
  io::IoStatus st;
  {
    const py::gil_scoped_release unlocked;
    st = io::convert_env_map(path, translated.settings, doc);
  }
  if (!st.ok()) raise_failure(st, layout, true);
  return document_dict(doc, translated.frame);
}

constexpr const char* kProjectDoc = R"(project(array, layout="auto", *, method="exact", seed=None, nonfinite="error",
        negative="keep", intensity=1.0, exposure=0.0, rotate=0.0, window="none", l1=False,
        extract_sun=False, extract_lights=0, cube_frame="unity", colorspace="linear-rec709",
        threads=0, frame="unity") -> dict

The document `shpack convert` writes for the same texels (json.loads of its JSON), from a
NumPy array of linear radiance: (H, W) grey, (H, W, C) with R, G, B first (C = 2 is grey and
alpha; channels after B are ignored), or (6, N, N, C) six cube faces in Unity's order
+X -X +Y -Y +Z -Z (layout "faces", or "auto"). float32 is read in place; float16 and float64
are converted to float32. The options are `shpack convert`'s (README.md), with the same
defaults; source.files and source.sha256 are empty, as no file was read. Raises ValueError
with the command's message for a bad option, array or texel.)";

constexpr const char* kConvertDoc = R"(convert(path, layout="auto", *, method="exact", seed=None, nonfinite="error",
        negative="keep", intensity=1.0, exposure=0.0, rotate=0.0, window="none", l1=False,
        extract_sun=False, extract_lights=0, cube_frame="unity", colorspace="auto",
        threads=0, frame="unity", layer=None, max_texels=None) -> dict

The document `shpack convert PATH` writes (json.loads of its JSON), read through lib/io
(OpenEXR, Radiance .hdr, PFM and, through shpack's OpenImageIO module, the other formats).
Raises ValueError for a bad option or texel, FileNotFoundError or OSError for a file that
cannot be read and RuntimeError for one that shpack cannot use, with the command's message.)";

}  // namespace
}  // namespace shpack::python

PYBIND11_MODULE(_shpack, m) {
  using shpack::python::Options;
  namespace sp = shpack::python;
  m.doc() = "Unity L2 spherical harmonics from HDR environment maps (shpack).";
  m.attr("__version__") = shpack::io::shpack_version();
  m.attr("__license__") = "Apache-2.0";  // LICENSE; also in the installed dist-info
  m.def(
      "project",
      [](const py::object& array, const std::string& layout, const std::string& method, const py::object& seed,
         const std::string& nonfinite, const std::string& negative, double intensity, double exposure, double rotate,
         const std::string& window, bool l1, bool extract_sun, const py::object& extract_lights,
         const std::string& cube_frame, const std::string& colorspace, const py::object& threads,
         const std::string& frame) {
        const Options options{method, nonfinite, negative, window, cube_frame, colorspace, frame, seed,
                              extract_lights, threads, intensity, exposure, rotate, l1, extract_sun};
        return sp::project(array, layout, options);
      },
      py::arg("array"), py::arg("layout") = "auto", py::kw_only(), py::arg("method") = "exact",
      py::arg("seed") = py::none(), py::arg("nonfinite") = "error", py::arg("negative") = "keep",
      py::arg("intensity") = 1.0, py::arg("exposure") = 0.0, py::arg("rotate") = 0.0, py::arg("window") = "none",
      py::arg("l1") = false, py::arg("extract_sun") = false, py::arg("extract_lights") = 0,
      py::arg("cube_frame") = "unity", py::arg("colorspace") = "linear-rec709", py::arg("threads") = 0,
      py::arg("frame") = "unity", sp::kProjectDoc);
  m.def(
      "convert",
      [](const std::filesystem::path& path, const std::string& layout, const std::string& method, const py::object& seed,
         const std::string& nonfinite, const std::string& negative, double intensity, double exposure, double rotate,
         const std::string& window, bool l1, bool extract_sun, const py::object& extract_lights,
         const std::string& cube_frame, const std::string& colorspace, const py::object& threads,
         const std::string& frame, const py::object& layer, const py::object& max_texels) {
        const Options options{method, nonfinite, negative, window, cube_frame, colorspace, frame, seed,
                              extract_lights, threads, intensity, exposure, rotate, l1, extract_sun};
        return sp::convert(path, layout, options, layer, max_texels);
      },
      py::arg("path"), py::arg("layout") = "auto", py::kw_only(), py::arg("method") = "exact",
      py::arg("seed") = py::none(), py::arg("nonfinite") = "error", py::arg("negative") = "keep",
      py::arg("intensity") = 1.0, py::arg("exposure") = 0.0, py::arg("rotate") = 0.0, py::arg("window") = "none",
      py::arg("l1") = false, py::arg("extract_sun") = false, py::arg("extract_lights") = 0,
      py::arg("cube_frame") = "unity", py::arg("colorspace") = "auto", py::arg("threads") = 0,
      py::arg("frame") = "unity", py::arg("layer") = py::none(), py::arg("max_texels") = py::none(), sp::kConvertDoc);
}
