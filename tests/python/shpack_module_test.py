"""The Python module `shpack` (python/shpack_module.cpp) against the shpack command.

Every numeric check compares shpack.project (or shpack.convert) with `shpack convert` on the
same texels written to a PFM file (float32, which the PFM reader gives back bit for bit), as
parsed JSON: Python's json reads each number to the same double the document wrote, so an
equal list is equal bit for bit. The whole document is compared, not only
sphericalHarmonicsL2, shader and radiance_sh; only source.files and source.sha256 differ,
since project() reads no file.

Run by ctest (tests/python/CMakeLists.txt) with Debian's /usr/bin/python3 and NumPy; the
environment names the command (SHPACK_CLI) and the repository (SHPACK_SOURCE_DIR), and
PYTHONPATH holds the built module.
"""

import json
import os
import pathlib
import subprocess
import tempfile
import struct
import threading
import time
import unittest
import zlib

import numpy as np

import shpack

CLI = os.environ["SHPACK_CLI"]
HDRI = pathlib.Path(os.environ["SHPACK_SOURCE_DIR"]) / "data" / "hdri"


def write_pfm(path, pixels):
    """A PFM file of float32 `pixels`, (H, W) grey or (H, W, 3), little-endian, rows bottom-up."""
    pixels = np.asarray(pixels, dtype="<f4")
    kind = b"Pf" if pixels.ndim == 2 else b"PF"
    height, width = pixels.shape[:2]
    with open(path, "wb") as out:
        out.write(kind + b"\n%d %d\n-1.0\n" % (width, height))
        out.write(np.ascontiguousarray(pixels[::-1]).tobytes())


def write_png(path, rgb):
    """An 8-bit RGB PNG of `rgb` (H, W, 3) uint8: no colour chunk, so it is read as sRGB."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    height, width = rgb.shape[:2]
    rows = b"".join(b"\0" + rgb[y].astype(np.uint8).tobytes() for y in range(height))
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n")
        out.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        out.write(chunk(b"IDAT", zlib.compress(rows)))
        out.write(chunk(b"IEND", b""))


def cli(*args):
    """`shpack ARGS`: (exit code, stdout, stderr)."""
    run = subprocess.run([CLI, *args], capture_output=True, text=True, check=False)
    return run.returncode, run.stdout, run.stderr


def cli_document(*args):
    code, out, err = cli("convert", *args)
    if code != 0:
        raise AssertionError(f"shpack convert {' '.join(args)}: exit {code}: {err}")
    return json.loads(out)


def cli_error(*args):
    """The one line `shpack convert ARGS` reports, without "shpack: " and the help's name."""
    code, _, err = cli("convert", *args)
    if code == 0:
        raise AssertionError(f"shpack convert {' '.join(args)} succeeded")
    line = err.rstrip("\n")
    assert line.startswith("shpack: "), line
    return code, line[len("shpack: "):].removesuffix(" (see shpack convert --help)")


def without_files(doc):
    """The document but for the names and digests of the files read."""
    doc = json.loads(json.dumps(doc))
    del doc["source"]["files"], doc["source"]["sha256"]
    return doc


def sky(height, width, channels=3, seed=0x5EED):
    """Varied positive radiance with a few negative texels, so that every coefficient counts."""
    rng = np.random.default_rng(seed)
    pixels = rng.uniform(-0.125, 2.0, size=(height, width, channels)).astype(np.float32)
    return pixels


def sunny_sky(height=64, width=128):
    """A smooth sky with a small, very bright sun and a second, dimmer lamp."""
    y, x = np.mgrid[0:height, 0:width].astype(np.float32)
    base = 0.2 + 0.3 * (1 - y / height)
    pixels = np.stack([base, base * 1.1, base * 1.3], axis=-1).astype(np.float32)
    pixels[10:12, 30:32] = [5000.0, 4800.0, 4500.0]
    pixels[40:42, 90:92] = [300.0, 320.0, 350.0]
    return pixels


class Scratch(unittest.TestCase):
    def setUp(self):
        self._dir = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self._dir.name)

    def tearDown(self):
        self._dir.cleanup()

    def pfm(self, pixels, name="map.pfm"):
        path = self.dir / name
        write_pfm(path, pixels)
        return str(path)


class ProjectEqualsTheCommand(Scratch):
    def assert_same(self, got, want):
        for key in ("sphericalHarmonicsL2", "shader", "radiance_sh"):
            self.assertEqual(got[key], want[key], key)
        self.assertEqual(without_files(got), without_files(want))

    def test_an_equirect_array_gives_the_document_of_its_pfm_file(self):
        pixels = sky(32, 64)
        got = shpack.project(pixels)
        want = cli_document(self.pfm(pixels))
        self.assert_same(got, want)
        self.assertEqual(got["source"]["files"], [])
        self.assertEqual(got["source"]["sha256"], [])
        self.assertEqual(got["source"]["layout"], "equirect")
        self.assertEqual((got["source"]["width"], got["source"]["height"]), (64, 32))
        self.assertEqual(len(got["sphericalHarmonicsL2"]), 3)
        self.assertEqual(len(got["sphericalHarmonicsL2"][0]), 9)

    def test_every_option_means_what_it_means_on_the_command_line(self):
        pixels = sky(32, 64)
        path = self.pfm(pixels)
        sunny = sunny_sky()
        sunny_path = self.pfm(sunny, "sunny.pfm")
        cases = [
            ({"intensity": 2.5}, ["--intensity", "2.5"], pixels, path),
            ({"exposure": -1.5}, ["--exposure", "-1.5"], pixels, path),
            ({"rotate": 30.0}, ["--rotate", "30"], pixels, path),
            ({"rotate": -117.25, "intensity": 0.75}, ["--rotate", "-117.25", "--intensity", "0.75"], pixels, path),
            ({"window": "hanning:3"}, ["--window", "hanning:3"], pixels, path),
            ({"window": "sloan"}, ["--window", "sloan"], pixels, path),
            ({"window": "optimal"}, ["--window", "optimal"], pixels, path),
            ({"l1": True}, ["--l1"], pixels, path),
            ({"negative": "clamp"}, ["--negative", "clamp"], pixels, path),
            ({"method": "center"}, ["--method", "center"], pixels, path),
            ({"method": "mc:512", "seed": 7}, ["--method", "mc:512", "--seed", "7"], pixels, path),
            ({"method": "fib:256"}, ["--method", "fib:256"], pixels, path),
            ({"colorspace": "acescg"}, ["--colorspace", "acescg"], pixels, path),
            ({"frame": "threejs"}, ["--frame", "threejs"], pixels, path),
            ({"frame": "unreal"}, ["--frame", "unreal"], pixels, path),
            ({"threads": 1}, ["--threads", "1"], pixels, path),
            ({"extract_sun": True}, ["--extract-sun"], sunny, sunny_path),
            ({"extract_sun": True, "rotate": 45.0}, ["--extract-sun", "--rotate", "45"], sunny, sunny_path),
            ({"extract_lights": 2}, ["--extract-lights", "2"], sunny, sunny_path),
            ({"extract_lights": 3, "window": "sloan"}, ["--extract-lights", "3", "--window", "sloan"], sunny,
             sunny_path),
        ]
        for options, flags, texels, file in cases:
            with self.subTest(options=options):
                self.assert_same(shpack.project(texels, **options), cli_document(file, *flags))

    def test_extraction_finds_the_sun_and_leaves_the_array_alone(self):
        sunny = sunny_sky()
        before = sunny.copy()
        doc = shpack.project(sunny, extract_sun=True)
        self.assertIsNotNone(doc["sun"])
        self.assertTrue(np.array_equal(sunny, before), "the caller's array was written")
        lights = shpack.project(sunny, extract_lights=2)
        self.assertGreaterEqual(len(lights["lights"]), 1)
        self.assertTrue(np.array_equal(sunny, before))

    def test_float16_and_float64_arrays_are_their_float32_values(self):
        pixels = sky(16, 32)
        want = cli_document(self.pfm(pixels))
        halves = pixels.astype(np.float16)
        self.assert_same(shpack.project(halves), cli_document(self.pfm(halves.astype(np.float32), "half.pfm")))
        self.assert_same(shpack.project(pixels.astype(np.float64)), want)  # float32 -> float64 -> float32 is exact
        doubles = np.random.default_rng(3).uniform(0, 1, size=(16, 32, 3))
        self.assert_same(shpack.project(doubles), shpack.project(doubles.astype(np.float32)))

    def test_a_strided_or_fortran_order_array_is_read_as_its_values(self):
        pixels = sky(16, 32, channels=4)
        self.assert_same(shpack.project(pixels[:, :, :3]), shpack.project(np.ascontiguousarray(pixels[:, :, :3])))
        self.assert_same(shpack.project(np.asfortranarray(pixels)), shpack.project(pixels))

    def test_a_grey_array_is_a_grey_file(self):
        grey = sky(16, 32)[:, :, 0]
        got = shpack.project(grey)
        self.assert_same(got, cli_document(self.pfm(grey)))
        self.assertEqual(got["sphericalHarmonicsL2"][0], got["sphericalHarmonicsL2"][2])
        self.assert_same(shpack.project(grey[:, :, np.newaxis]), got)

    def test_channels_after_rgb_are_ignored_and_counted(self):
        pixels = sky(16, 32, channels=5)
        got = shpack.project(pixels)
        want = cli_document(self.pfm(pixels[:, :, :3]))
        self.assertEqual(got["diagnostics"]["ignored_channels"], 2)
        want["diagnostics"]["ignored_channels"] = 2
        self.assert_same(got, want)

    def test_a_cross_is_a_cross_file(self):
        cross = sky(12, 16)  # 4:3, a horizontal cross of 4x4 faces
        got = shpack.project(cross)
        self.assertEqual(got["source"]["layout"], "hcross")
        self.assert_same(got, cli_document(self.pfm(cross)))
        self.assert_same(shpack.project(cross, cube_frame="gl"), cli_document(self.pfm(cross), "--cube-frame", "gl"))
        strip = sky(4, 24)
        self.assert_same(shpack.project(strip, "hstrip"), cli_document(self.pfm(strip), "--layout", "hstrip"))

    def test_a_square_sphere_map_needs_its_layout(self):
        square = sky(16, 16)
        for layout in ("octahedral", "angular", "mirrorball"):
            with self.subTest(layout=layout):
                self.assert_same(shpack.project(square, layout), cli_document(self.pfm(square), "--layout", layout))
        with self.assertRaisesRegex(ValueError, r"^array: the layout of a 16x16 image is ambiguous"):
            shpack.project(square)

    def test_six_faces_are_six_face_files(self):
        faces = np.stack([sky(8, 8, seed=f) for f in range(6)])
        files = [self.pfm(face, f"face{f}.pfm") for f, face in enumerate(faces)]
        want = cli_document("--faces", *files)
        got = shpack.project(faces, "faces")
        self.assertEqual(got["source"]["layout"], "faces")
        self.assert_same(got, want)
        self.assert_same(shpack.project(faces), want)  # auto: a 4-D array is six faces
        self.assert_same(shpack.project(faces, cube_frame="threejs", intensity=3.0),
                         cli_document("--faces", *files, "--cube-frame", "threejs", "--intensity", "3"))

    def test_nonfinite_zero_counts_what_it_replaced(self):
        pixels = sky(16, 32)
        pixels[3, 5, 1] = np.nan
        pixels[9, 2, 0] = np.inf
        got = shpack.project(pixels, nonfinite="zero")
        self.assert_same(got, cli_document(self.pfm(pixels), "--nonfinite", "zero"))
        self.assertEqual(got["diagnostics"]["nonfinite_texels"], 2)

    def test_the_gil_is_released_while_converting(self):
        # The main thread keeps running Python while a worker converts. Were the GIL held,
        # the main thread would stop for a whole conversion (tens of milliseconds here); as
        # it is released, the longest pause of the main thread is the scheduler's.
        pixels = sky(2048, 4096)
        state = {"inside": False, "done": False, "durations": []}

        def work():
            state["inside"] = True
            for _ in range(3):
                start = time.perf_counter()
                shpack.project(pixels, threads=1)
                state["durations"].append(time.perf_counter() - start)
            state["done"] = True

        worker = threading.Thread(target=work)
        worker.start()
        while not state["inside"]:
            pass
        longest_pause, last = 0.0, time.perf_counter()
        while not state["done"]:
            now = time.perf_counter()
            longest_pause, last = max(longest_pause, now - last), now
        worker.join()
        shortest_conversion = min(state["durations"])
        self.assertLess(longest_pause, shortest_conversion / 2,
                        f"the main thread paused {longest_pause:.3f} s during {shortest_conversion:.3f} s conversions")


class ConvertEqualsTheCommand(Scratch):
    def test_a_file_gives_the_command_s_document(self):
        exr = str(HDRI / "studio.exr")
        self.assertEqual(shpack.convert(exr), cli_document(exr))
        self.assertEqual(shpack.convert(pathlib.Path(exr), window="sloan", rotate=90.0),
                         cli_document(exr, "--window", "sloan", "--rotate", "90"))
        self.assertEqual(shpack.convert(exr, extract_sun=True), cli_document(exr, "--extract-sun"))
        pixels = sky(16, 32)
        pfm = self.pfm(pixels)
        self.assertEqual(shpack.convert(pfm, method="qmc:128", seed=3),
                         cli_document(pfm, "--method", "qmc:128", "--seed", "3"))
        self.assertEqual(without_files(shpack.convert(pfm)), without_files(shpack.project(pixels)))

    def test_other_formats_are_read_through_the_openimageio_module(self):
        # The module beside the Python module (python/CMakeLists.txt), found by lib/io.
        png = self.dir / "sky.png"
        write_png(png, np.random.default_rng(5).integers(0, 256, size=(8, 16, 3)))
        self.assertEqual(shpack.convert(png), cli_document(str(png)))

    def test_file_errors_are_the_command_s_lines(self):
        missing = str(self.dir / "missing.exr")
        with self.assertRaises(FileNotFoundError) as raised:
            shpack.convert(missing)
        self.assertEqual(str(raised.exception), cli_error(missing)[1])
        with self.assertRaises(OSError) as raised:
            shpack.convert(str(self.dir))
        self.assertEqual(str(raised.exception), cli_error(str(self.dir))[1])
        junk = self.dir / "junk.exr"
        junk.write_bytes(b"not an image at all")
        with self.assertRaises(OSError) as raised:
            shpack.convert(str(junk))
        self.assertEqual(str(raised.exception), cli_error(str(junk))[1])
        pfm = self.pfm(sky(16, 32))
        with self.assertRaises(RuntimeError) as raised:
            shpack.convert(pfm, max_texels=100)
        self.assertEqual(str(raised.exception), cli_error(pfm, "--max-texels", "100")[1])
        exr = str(HDRI / "studio.exr")
        with self.assertRaises(RuntimeError) as raised:
            shpack.convert(exr, layer="diffuse")
        self.assertEqual(str(raised.exception), cli_error(exr, "--layer", "diffuse")[1])
        odd = self.pfm(sky(5, 7), "odd.pfm")
        with self.assertRaises(ValueError) as raised:
            shpack.convert(odd)
        self.assertEqual(str(raised.exception), cli_error(odd)[1])
        self.assertEqual(shpack.convert(odd, "equirect"), cli_document(odd, "--layout", "equirect"))

    def test_a_nan_is_named_where_the_command_names_it(self):
        pixels = sky(16, 32)
        pixels[6, 11, 2] = np.nan
        pfm = self.pfm(pixels)
        with self.assertRaises(ValueError) as from_file:
            shpack.convert(pfm)
        self.assertEqual(str(from_file.exception), cli_error(pfm)[1])
        with self.assertRaises(ValueError) as from_array:
            shpack.project(pixels)
        self.assertEqual(str(from_array.exception),
                         "array" + str(from_file.exception).removeprefix(pfm))
        self.assertIn("1 NaN/Inf texels (first at x=11, y=6)", str(from_array.exception))
        self.assertIn("use --nonfinite=zero", str(from_array.exception))


class BadInputsRaiseValueError(unittest.TestCase):
    def test_arrays_that_are_not_maps(self):
        pixels = sky(8, 16)
        cases = [
            (pixels.astype(np.int32), r"^array: dtype int32 is not float16, float32 or float64$"),
            (pixels.astype(np.complex64), r"^array: dtype complex64 is not float16, float32 or float64$"),
            (np.zeros(16, np.float32), r"^array: shape \(16,\) is not \(H, W\), \(H, W, C\)"),
            (np.zeros((2, 2, 2, 2, 3), np.float32), r"^array: shape \(2, 2, 2, 2, 3\) is not"),
            (np.zeros((0, 16, 3), np.float32), r"^array: shape \(0, 16, 3\) has no texels$"),
            (np.zeros((8, 16, 0), np.float32), r"^array: shape \(8, 16, 0\) has no texels$"),
            (np.zeros((5, 4, 4, 3), np.float32), r"^array: shape \(5, 4, 4, 3\) is not six faces"),
            (np.zeros((6, 4, 5, 3), np.float32), r"^array: shape \(6, 4, 5, 3\) has faces that are not square$"),
            ("sky", r"^array: dtype <U3 is not float16"),
        ]
        for array, message in cases:
            with self.subTest(message=message):
                with self.assertRaisesRegex(ValueError, message):
                    shpack.project(array)

    def test_layouts_that_do_not_fit_the_array(self):
        with self.assertRaisesRegex(ValueError, r"^array: shape \(8, 16, 3\) is not \(6, N, N, C\)"):
            shpack.project(sky(8, 16), "faces")
        with self.assertRaisesRegex(ValueError, r"^array: shape \(6, 4, 4, 3\) is six faces"):
            shpack.project(np.zeros((6, 4, 4, 3), np.float32), "equirect")
        with self.assertRaisesRegex(ValueError, r"^array: .*hcross"):
            shpack.project(sky(8, 16), "hcross")
        with self.assertRaisesRegex(ValueError, r"^array: --extract-sun reads equirect maps only$"):
            shpack.project(sky(12, 16), extract_sun=True)

    def test_a_nan_under_nonfinite_error(self):
        pixels = sky(8, 16)
        pixels[2, 3, 0] = np.nan
        with self.assertRaisesRegex(ValueError, r"^array: 1 NaN/Inf texels \(first at x=3, y=2\); use --nonfinite=zero"):
            shpack.project(pixels)
        faces = np.ones((6, 4, 4, 3), np.float32)
        faces[4, 1, 2, 1] = np.inf
        with self.assertRaisesRegex(ValueError, r"^array\[4\]: 1 NaN/Inf texels \(first at x=2, y=1\)"):
            shpack.project(faces)

    def test_options_are_refused_in_the_command_s_words(self):
        # project() and convert() refuse what the command refuses, with its line.
        exr = str(HDRI / "studio.exr")
        cases = [
            ({"method": "fast"}, ["--method", "fast"]),
            ({"method": "mc:0"}, ["--method", "mc:0"]),
            ({"window": "hanning:x"}, ["--window", "hanning:x"]),
            ({"window": "blur"}, ["--window", "blur"]),
            ({"intensity": -1.0}, ["--intensity", "-1"]),
            ({"rotate": float("inf")}, ["--rotate", "inf"]),
            ({"exposure": float("nan")}, ["--exposure", "nan"]),
            ({"seed": -3}, ["--seed", "-3"]),
            ({"extract_lights": 9}, ["--extract-lights", "9"]),
            ({"threads": -1}, ["--threads", "-1"]),
            ({"layout": "diagonal"}, ["--layout", "diagonal"]),
            ({"nonfinite": "maybe"}, ["--nonfinite", "maybe"]),
            ({"negative": "abs"}, ["--negative", "abs"]),
            ({"colorspace": "srgb"}, ["--colorspace", "srgb"]),
            ({"cube_frame": "dx"}, ["--cube-frame", "dx"]),
            ({"frame": "zz"}, ["--frame", "zz"]),
            ({"method": "mc:64:5", "seed": 5}, ["--method", "mc:64:5", "--seed", "5"]),
            ({"intensity": 1e300, "exposure": 100.0}, ["--intensity", "1e300", "--exposure", "100"]),
        ]
        for options, flags in cases:
            with self.subTest(options=options):
                code, line = cli_error(exr, *flags)
                self.assertEqual(code, 2)
                with self.assertRaises(ValueError) as raised:
                    shpack.convert(exr, **options)
                self.assertEqual(str(raised.exception), line.removeprefix("convert: "))
                if "layout" not in options:  # project() also names "faces" among its layouts
                    with self.assertRaises(ValueError) as raised:
                        shpack.project(sky(8, 16), **options)
                    self.assertEqual(str(raised.exception), line.removeprefix("convert: "))
        with self.assertRaisesRegex(ValueError, r"^--layout: diagonal not in \{auto,.*,mirrorball,faces\}$"):
            shpack.project(sky(8, 16), "diagonal")
        with self.assertRaisesRegex(ValueError, r"^array: --extract-sun and --extract-lights exclude each other"):
            shpack.project(sky(8, 16), extract_sun=True, extract_lights=1)
        with self.assertRaisesRegex(ValueError, r"^--threads: '1.5' is not an unsigned integer$"):
            shpack.project(sky(8, 16), threads=1.5)


class Module(unittest.TestCase):
    def test_the_version_is_the_command_s(self):
        code, out, _ = cli("--version")
        self.assertEqual(code, 0)
        self.assertEqual(out.strip(), "shpack " + shpack.__version__)
        self.assertEqual(shpack.project(sky(8, 16))["generator"], "shpack " + shpack.__version__)


if __name__ == "__main__":
    unittest.main()
